using System.Text;
using AcShadow.Analysis.Chart.Cells;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>Every file a chart run writes, in a fixed order: chart.csv, summary.csv, failures.csv, speed-accuracy.svg, one failure map per object.</summary>
public static class ChartFiles
{
    public static IReadOnlyList<ChartFile> Render(ChartReport report)
    {
        var files = new List<ChartFile>
        {
            Utf8("chart.csv", ChartCsv.Write(report)),
            Utf8("summary.csv", SummaryCsv.Write(report)),
            Utf8("failures.csv", FailuresCsv.Write(report)),
            Utf8("speed-accuracy.svg", SpeedAccuracySvg.Write(report)),
        };
        foreach (var chart in report.Objects) files.Add(Utf8(FailureMapSvg.FileName(chart.SetupId), FailureMapSvg.Write(report, chart)));
        return files;
    }

    /// <summary>
    /// The files a run over these objects writes, each with the start of its content (its header row or
    /// root element): for checking, before any object is charted, that no file acshadow does not own would
    /// be replaced. <paramref name="cells"/>: a landblock's indoor cells are charted too (cells.csv).
    /// </summary>
    public static IEnumerable<ChartFile> Heads(IEnumerable<uint> objectIds, bool cells = false)
    {
        var svg = new UTF8Encoding(false).GetBytes(new SvgDocument(1, 1).Render());
        yield return Utf8("chart.csv", ChartCsv.Header + "\n");
        yield return Utf8("summary.csv", SummaryCsv.Header + "\n");
        yield return Utf8("failures.csv", FailuresCsv.Header + "\n");
        yield return new ChartFile("speed-accuracy.svg", svg);
        if (cells) yield return Utf8(CellsCsv.FileName, CellsCsv.Header + "\n");
        foreach (var id in objectIds) yield return new ChartFile(FailureMapSvg.FileName(id), svg);
    }

    /// <summary>One object's failure map, rendered as soon as the object is charted.</summary>
    public static ChartFile FailureMap(ChartOptions options, IReadOnlyList<string> models, ObjectChart chart) =>
        Utf8(FailureMapSvg.FileName(chart.SetupId), FailureMapSvg.Write(new ChartReport(options, models, []), chart));

    private static ChartFile Utf8(string path, string text) => new(path, new UTF8Encoding(false).GetBytes(text));
}
