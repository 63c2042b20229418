using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Catalog;
using AcShadow.Core.Formats;
using AcShadow.Core.Movement;
using AcShadow.Forging;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>`chart --movement` on the built-in sample, as the command streams it, with fixed timers: every object's movement chart and every movement file in memory.</summary>
internal static class SampleMovementChart
{
    public const string OffsetWalk = "closed/out-in/lat+0.450/hdg+00/walk";

    public static MovementChartOptions Options { get; } = new(
        MoverSetup.Read(SampleChart.Subjects.Value.Dat, SampleDats.MoverSetup)!, id => DoorCatalog.Find(id) is not null) { Walk = OffsetWalk };

    public static (IReadOnlyList<ObjectMovementChart> Charts, IReadOnlyList<OutputFile> Files) Run(IReadOnlyList<uint> setups, int jobs = 1,
        IReadOnlyList<IShapeModel>? models = null)
    {
        models ??= ShapeModels.All;
        var subjects = SampleChart.Subjects.Value;
        var charts = new List<ObjectMovementChart>();
        var files = new List<OutputFile>();
        using var csv = new StringWriter();
        var movementFiles = MovementFiles.Begin(csv);
        var options = new ChartOptions { Spacing = 0.5f, TimingBatches = 1, TimingProbes = 16, WarmupPasses = 0, MaxStabilityProbes = 2000 };
        var tally = ChartRunner.Stream(setups.Count, i => subjects.For(setups[i]), options, chart =>
        {
            charts.Add(chart.Movement!);
            files.AddRange(movementFiles.Add(chart.Movement!));
        }, models, new FixedTimer(), jobs: jobs, movement: Options, transitionTimer: new FixedTransitionTimer());
        files.Insert(0, OutputFile.Text(MovementFiles.ChartFile, csv.ToString()));
        files.Add(MovementFiles.Summary(tally.Movement.Summaries()));
        files.Add(ChartFiles.Totals(options, [.. models.Select(m => m.Name)], tally.Objects, tally.Summaries(), tally.Movement.Summaries())
            .Single(f => f.RelativePath == "speed-accuracy.svg"));
        return (charts, files);
    }

    private static readonly Lazy<ObjectMovementChart> DoorChart = new(() => Run([SampleChart.Door]).Charts.Single());

    public static ObjectMovementChart Door => DoorChart.Value;
}
