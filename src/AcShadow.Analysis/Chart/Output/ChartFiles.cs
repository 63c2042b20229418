using System.Text;
using AcShadow.Core.Formats;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// Every file a chart run writes, as the run writes them: chart.csv and failures.csv grow by each object's
/// rows, each object's failure map is whole as soon as the object is charted, and summary.csv and
/// speed-accuracy.svg are made from the run's totals at the end, so memory does not grow with the number
/// of objects.
/// </summary>
public sealed class ChartFiles
{
    private readonly TextWriter _chartCsv;
    private readonly TextWriter _failuresCsv;
    private readonly ChartOptions _options;
    private readonly string _reference;

    private ChartFiles(TextWriter chartCsv, TextWriter failuresCsv, ChartOptions options, IReadOnlyList<string> models)
    {
        _chartCsv = chartCsv;
        _failuresCsv = failuresCsv;
        _options = options;
        _reference = models[0];
    }

    /// <summary>Starts chart.csv and failures.csv (their header rows) on these writers; <paramref name="models"/> in order, the reference first.</summary>
    public static ChartFiles Begin(TextWriter chartCsv, TextWriter failuresCsv, ChartOptions options, IReadOnlyList<string> models)
    {
        chartCsv.Write(ChartCsv.Header + "\n");
        failuresCsv.Write(FailuresCsv.Header + "\n");
        return new ChartFiles(chartCsv, failuresCsv, options, models);
    }

    /// <summary>Adds one charted object's rows to chart.csv and failures.csv, and gives its failure map.</summary>
    public OutputFile Add(ObjectChart chart)
    {
        _chartCsv.Write(ChartCsv.Rows(chart));
        _failuresCsv.Write(FailuresCsv.Rows(chart));
        return OutputFile.Text(FailureMapSvg.FileName(chart.SetupId), FailureMapSvg.Write(_options, _reference, chart));
    }

    /// <summary>summary.csv and speed-accuracy.svg, from the totals of a run over <paramref name="objects"/> objects.</summary>
    /// <param name="movement">The movement chart's totals (`chart --movement`): movement-summary.csv, and speed-accuracy.svg gains movement accuracy.</param>
    public static IReadOnlyList<OutputFile> Totals(ChartOptions options, IReadOnlyList<string> models, int objects, IReadOnlyList<ModelSummary> summaries,
        IReadOnlyList<Movement.MovementSummary>? movement = null) =>
    [
        OutputFile.Text("summary.csv", SummaryCsv.Write(summaries)),
        OutputFile.Text("speed-accuracy.svg", SpeedAccuracySvg.Write(options, models[0], objects, summaries, movement)),
        .. movement is null ? Array.Empty<OutputFile>() : [MovementFiles.Summary(movement)],
    ];

    /// <summary>
    /// The files a run over these objects writes, each with the start of its content (its header row or
    /// root element): for checking, before any object is charted, that no file acshadow does not own would
    /// be replaced. <paramref name="cells"/>: cells.csv's, when a landblock's indoor cells are charted too.
    /// </summary>
    public static IEnumerable<OutputFile> Heads(IEnumerable<uint> objectIds, OutputFile? cells = null)
    {
        var svg = new UTF8Encoding(false).GetBytes(new SvgDocument(1, 1).Render());
        yield return OutputFile.Text("chart.csv", ChartCsv.Header + "\n");
        yield return OutputFile.Text("summary.csv", SummaryCsv.Header + "\n");
        yield return OutputFile.Text("failures.csv", FailuresCsv.Header + "\n");
        yield return new OutputFile("speed-accuracy.svg", svg);
        if (cells is not null) yield return cells;
        foreach (var id in objectIds) yield return new OutputFile(FailureMapSvg.FileName(id), svg);
    }

    }
