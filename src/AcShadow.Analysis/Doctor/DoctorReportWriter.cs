using System.Globalization;
using System.Text;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The doctor report as JSON (<see cref="FileFormats.Doctor"/>) and as the one-screen summary the command prints. Both hold only
/// ids, counts, hashes, verdicts and fixed text. LF line ends, invariant culture.
/// </summary>
public static class DoctorReportWriter
{
    public static byte[] Json(DoctorReport report)
    {
        var root = new JsonObj()
            .Add("format", FileFormats.Doctor.Format)
            .Add("toolVersion", report.ToolVersion)
            .Add("dat", Facts(report.Portal))
            .Add("cellDat", report.Cell is null ? JsonNull.Value : Facts(report.Cell))
            .Add("verdicts", new JsonObj()
                .Add("holds", report.Count(DoctorVerdict.Holds))
                .Add("differs", report.Count(DoctorVerdict.Differs))
                .Add("notApplicable", report.Count(DoctorVerdict.NotApplicable))
                .Add("notChecked", report.Count(DoctorVerdict.NotChecked)))
            .Add("checks", JsonArr.Of(report.Checks, Check));
        return CanonicalJsonWriter.WriteUtf8(root);
    }

    private static JsonObj Facts(DoctorDatFacts facts) => new JsonObj()
        .Add("kind", facts.Kind)
        .Add("fileLength", facts.FileLength)
        .Add("headerFileSize", facts.HeaderFileSize)
        .Add("blockSize", facts.BlockSize)
        .Add("entries", facts.Entries)
        .Add("maxEntryIteration", facts.MaxEntryIteration)
        .Add("entriesByIdHighByte", Counts(facts.EntriesByType));

    private static JsonObj Check(DoctorCheck check)
    {
        var obj = new JsonObj()
            .Add("key", check.Key)
            .Add("section", check.Section)
            .Add("verdict", check.Verdict.Text())
            .Add("claim", check.Claim)
            .Add("headline", check.Headline)
            .Add("counts", Counts(check.Counts))
            .Add("exampleKind", check.ExampleKind)
            .Add("examples", JsonArr.Of(check.Examples.Select(JsonIds.Format)));
        if (check.Histogram is { } histogram) obj.Add(check.HistogramName ?? "histogram", Counts(histogram));
        if (check.Digests is { } digests)
        {
            var d = new JsonObj();
            foreach (var (name, hex) in digests) d.Add(name, hex);
            obj.Add("sha256", d);
        }
        if (check.Measured is { } measured)
        {
            var m = new JsonObj();
            foreach (var (name, value) in measured) m.Add(name, JsonNum.Of(value));
            obj.Add("measured", m);
        }
        return obj;
    }

    private static JsonObj Counts(IEnumerable<KeyValuePair<string, long>> counts)
    {
        var obj = new JsonObj();
        foreach (var (name, value) in counts) obj.Add(name, value);
        return obj;
    }

    /// <summary>A verdict a line, grouped by section, the first ids of what differs, and the totals: one screen.</summary>
    public static string Summary(DoctorReport report, string datDescription)
    {
        var sb = new StringBuilder();
        sb.Append("acshadow doctor ").Append(report.ToolVersion).Append(" on ").Append(datDescription).Append('\n');
        var p = report.Portal;
        sb.Append(Inv($"  portal dat: {p.FileLength} bytes, block size {p.BlockSize}, {p.Entries} entries, iteration {p.MaxEntryIteration}\n"));
        if (report.Cell is { } c)
            sb.Append(Inv($"  cell dat:   {c.FileLength} bytes, block size {c.BlockSize}, {c.Entries} entries, iteration {c.MaxEntryIteration}\n"));
        else sb.Append("  cell dat:   not checked (none given: pass --cell-dat, keep client_cell_1.dat in the folder --dat names, or set ACSHADOW_CELL_DAT)\n");
        var width = report.Checks.Max(k => k.Key.Length);
        // The widest verdict ("not applicable") and two spaces: the columns never run together.
        var verdictWidth = Enum.GetValues<DoctorVerdict>().Max(v => v.Text().Length) + 2;
        foreach (var section in report.Checks.GroupBy(k => k.Section))
        {
            sb.Append('\n').Append(section.Key switch { DoctorChecks.Reading => "Reading", DoctorChecks.Retail => "Retail rules", _ => "The tool" }).Append('\n');
            foreach (var check in section)
            {
                sb.Append("  ").Append(check.Verdict.Text().PadRight(verdictWidth)).Append(check.Key.PadRight(width + 2)).Append(check.Headline).Append('\n');
                if (check.Verdict == DoctorVerdict.Differs && check.Examples.Count > 0)
                    sb.Append("  ").Append(' ', verdictWidth + width + 2).Append(check.ExampleKind).Append(' ')
                      .Append(string.Join(' ', check.Examples.Take(5).Select(JsonIds.Format)))
                      .Append(check.Examples.Count > 5 ? " …" : "").Append('\n');
            }
        }
        sb.Append(Inv($"\n{report.Count(DoctorVerdict.Holds)} hold, {report.Count(DoctorVerdict.Differs)} differ, {report.Count(DoctorVerdict.NotApplicable)} not applicable, {report.Count(DoctorVerdict.NotChecked)} not checked{(report.Cell is null ? "; the cell dat's LandBlockInfos not checked (no cell dat)" : "")}\n"));
        return sb.ToString();
    }

    private static string Inv(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
