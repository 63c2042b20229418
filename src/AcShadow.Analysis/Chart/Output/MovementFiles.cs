using AcShadow.Analysis.Chart.Movement;
using AcShadow.Core.Formats;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// The files `chart --movement` adds, as the run writes them: movement-chart.csv grows by each object's rows,
/// each object's movement map (and, with --walk, its walk drawings) is whole as soon as the object is charted,
/// and movement-summary.csv is made from the run's totals at the end.
/// </summary>
public sealed class MovementFiles
{
    public const string ChartFile = "movement-chart.csv", SummaryFile = "movement-summary.csv";

    private readonly TextWriter _csv;

    private MovementFiles(TextWriter csv) => _csv = csv;

    /// <summary>Starts movement-chart.csv (its header row) on this writer.</summary>
    public static MovementFiles Begin(TextWriter csv)
    {
        csv.Write(MovementChartCsv.Header + "\n");
        return new MovementFiles(csv);
    }

    /// <summary>Adds one object's rows to movement-chart.csv, and gives its movement map and walk drawings.</summary>
    public IReadOnlyList<OutputFile> Add(ObjectMovementChart chart)
    {
        _csv.Write(MovementChartCsv.Rows(chart));
        return
        [
            OutputFile.Text(MovementMapSvg.FileName(chart.SetupId), MovementMapSvg.Write(chart)),
            .. MovementWalkSvg.Write(chart).Select(w => OutputFile.Text(MovementWalkSvg.FileName(chart.SetupId, w.Model), w.Svg)),
        ];
    }

    public static OutputFile Summary(IReadOnlyList<MovementSummary> summaries) => OutputFile.Text(SummaryFile, MovementSummaryCsv.Write(summaries));

    /// <summary>The movement files a run over these objects writes, with the start of each (for checking no foreign file is replaced).</summary>
    public static IEnumerable<OutputFile> Heads(IEnumerable<uint> objectIds)
    {
        var svg = new SvgDocument(1, 1).Render();
        yield return OutputFile.Text(ChartFile, MovementChartCsv.Header + "\n");
        yield return OutputFile.Text(SummaryFile, MovementSummaryCsv.Header + "\n");
        foreach (var id in objectIds) yield return OutputFile.Text(MovementMapSvg.FileName(id), svg);
    }
}
