using System.Text;
using AcShadow.Analysis.Reports;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// Renders an <see cref="AuditReport"/>. Table and Markdown end with the summary block; JSON carries it
/// as "summary"; CSV holds rows only (so it stays one table) and the caller prints the summary apart.
/// Text uses LF line ends and invariant culture, so the output is the same on every machine.
/// </summary>
public static class AuditWriter
{
    public static string Write(AuditReport report, AuditFormat format, DatSourceInfo dat, BatchSelection selection) => format switch
    {
        AuditFormat.Table => Table(report),
        AuditFormat.Csv => Csv(report),
        AuditFormat.Json => CanonicalJsonWriter.Write(Json(report, dat, selection)),
        AuditFormat.Markdown => Markdown(report, dat, selection),
        _ => throw new ArgumentOutOfRangeException(nameof(format)),
    };

    public static string Table(AuditReport report)
    {
        var columns = report.Columns;
        var cells = report.Rows.Select(r => columns.Select(c => c.Text(r, "-")).ToArray()).ToArray();
        var widths = columns.Select((c, i) => Math.Max(c.Header.Length, cells.Length == 0 ? 0 : cells.Max(row => row[i].Length))).ToArray();
        var sb = new StringBuilder();
        sb.Append(Line(columns.Select(c => c.Header).ToArray(), widths)).Append('\n');
        sb.Append(Line(widths.Select(w => new string('-', w)).ToArray(), widths)).Append('\n');
        foreach (var row in cells) sb.Append(Line(row, widths)).Append('\n');
        sb.Append('\n').Append(SummaryText(report));
        return sb.ToString();
    }

    /// <summary>The summary block: one "count  label" line per category, and the skipped ids.</summary>
    public static string SummaryText(AuditReport report)
    {
        var sb = new StringBuilder();
        sb.Append($"Summary ({report.Rows.Count} of {report.Audited} audited Setup(s) shown)\n");
        var width = report.Summary.Counts.Max(c => c.Count.ToString(System.Globalization.CultureInfo.InvariantCulture).Length);
        foreach (var (_, label, count) in report.Summary.Counts)
            sb.Append("  ").Append(count.ToString(System.Globalization.CultureInfo.InvariantCulture).PadLeft(width)).Append("  ").Append(label).Append('\n');
        foreach (var group in report.Skipped.GroupBy(s => s.Reason))
            sb.Append($"  skipped, {group.Key}: {string.Join(' ', group.Select(s => JsonIds.Format(s.Id)))}\n");
        return sb.ToString();
    }

    public static string Csv(AuditReport report)
    {
        var sb = new StringBuilder();
        sb.Append(string.Join(',', report.Columns.Select(c => CsvField.Of(c.Key)))).Append('\n');
        foreach (var row in report.Rows)
            sb.Append(string.Join(',', report.Columns.Select(c => CsvField.Of(c.Text(row, ""))))).Append('\n');
        return sb.ToString();
    }

    public static JsonObj Json(AuditReport report, DatSourceInfo dat, BatchSelection selection) => new JsonObj()
        .Add("format", FileFormats.Audit.Format)
        .Add("dat", BatchIndexWriter.Dat(dat))
        .Add("selection", selection.Describe())
        .Add("audited", report.Audited)
        .Add("rows", JsonArr.Of(report.Rows, r =>
        {
            var obj = new JsonObj();
            foreach (var c in report.Columns) obj.Add(c.Key, c.Json(r));
            return obj;
        }))
        .Add("summary", report.Summary.Counts.Aggregate(new JsonObj(), (o, c) => o.Add(c.Key, c.Count)))
        .Add("skipped", JsonArr.Of(report.Skipped, s => new JsonObj()
            .Add("id", JsonIds.Format(s.Id)).Add("reason", s.Reason).Add("from", JsonArr.Of(s.From.Names()))));

    public static string Markdown(AuditReport report, DatSourceInfo dat, BatchSelection selection)
    {
        var sb = new StringBuilder();
        sb.Append($"# acshadow audit\n\nDat `{dat.FileName}` ({dat.Size} bytes, iteration {dat.Iteration} from the {dat.IterationSource.Describe()}); selection `{selection.Describe()}`.\n\n");
        sb.Append("| ").Append(string.Join(" | ", report.Columns.Select(c => c.Header))).Append(" |\n");
        sb.Append('|').Append(string.Concat(report.Columns.Select(_ => "---|"))).Append('\n');
        foreach (var row in report.Rows)
            sb.Append("| ").Append(string.Join(" | ", report.Columns.Select(c => c.Text(row, "-").Replace("|", "\\|")))).Append(" |\n");
        sb.Append("\n## Summary\n\n");
        sb.Append($"{report.Rows.Count} of {report.Audited} audited Setup(s) shown.\n\n");
        foreach (var (_, label, count) in report.Summary.Counts) sb.Append($"- {label}: {count}\n");
        foreach (var group in report.Skipped.GroupBy(s => s.Reason))
            sb.Append($"- skipped, {group.Key}: {string.Join(' ', group.Select(s => JsonIds.Format(s.Id)))}\n");
        return sb.ToString();
    }

    private static string Line(string[] cells, int[] widths) =>
        string.Join("  ", cells.Select((c, i) => c.PadRight(widths[i]))).TrimEnd();

}
