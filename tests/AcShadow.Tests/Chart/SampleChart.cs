using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Dat;
using AcShadow.Core.Formats;
using AcShadow.Forging;

namespace AcShadow.Tests.Chart;

/// <summary>Chart runs on the built-in sample with the fixed timer, computed once per options.</summary>
internal static class SampleChart
{
    internal static readonly Lazy<ChartSubjects> Subjects = new(() =>
    {
        var (portal, _) = SampleDats.Build();
        return new ChartSubjects(DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat"));
    });

    public const uint Door = 0x020019FF;

    public static SampleRun Run(ChartOptions? options = null, params uint[] setups) =>
        Run([.. setups.Select(id => Subjects.Value.For(id)!)], options ?? new ChartOptions(), timer: new FixedTimer());

    /// <summary>
    /// Charts the subjects the way <c>acshadow chart</c> does (<see cref="ChartRunner.Stream"/> writing
    /// <see cref="ChartFiles"/>), keeping every object's chart and every file in memory.
    /// </summary>
    public static SampleRun Run(IReadOnlyList<ChartSubject> subjects, ChartOptions options, IReadOnlyList<IShapeModel>? models = null, IQueryTimer? timer = null)
    {
        models ??= ShapeModels.All;
        var names = models.Select(m => m.Name).ToArray();
        var charts = new List<ObjectChart>();
        var maps = new List<OutputFile>();
        using var chartCsv = new StringWriter();
        using var failuresCsv = new StringWriter();
        var files = ChartFiles.Begin(chartCsv, failuresCsv, options, names);
        var tally = ChartRunner.Stream(subjects.Count, i => subjects[i], options, chart =>
        {
            charts.Add(chart);
            maps.Add(files.Add(chart));
        }, models, timer);
        var totals = ChartFiles.Totals(options, names, tally.Objects, tally.Summaries());
        OutputFile[] all =
        [
            OutputFile.Text("chart.csv", chartCsv.ToString()), totals.Single(f => f.RelativePath == "summary.csv"),
            OutputFile.Text("failures.csv", failuresCsv.ToString()), totals.Single(f => f.RelativePath == "speed-accuracy.svg"), .. maps,
        ];
        return new SampleRun(options, names, charts, all);
    }

    private static readonly Lazy<SampleRun> DoorReport = new(() => Run(null, Door));

    public static SampleRun DoorOnly => DoorReport.Value;
}

/// <summary>One chart run's options, models (the reference first), charts in subject order, and files in the order a run finishes them.</summary>
internal sealed record SampleRun(ChartOptions Options, IReadOnlyList<string> Models, IReadOnlyList<ObjectChart> Objects, IReadOnlyList<OutputFile> Files)
{
    public string Reference => Models[0];

    public string Text(string path) => System.Text.Encoding.UTF8.GetString(Files.Single(f => f.RelativePath == path).Content.Span);
}
