using System.Text;

namespace AcShadow.Core.Chart.Output;

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

    private static ChartFile Utf8(string path, string text) => new(path, new UTF8Encoding(false).GetBytes(text));
}
