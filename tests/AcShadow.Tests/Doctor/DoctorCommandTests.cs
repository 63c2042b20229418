using System.Globalization;
using System.Text.Json;
using System.Text.RegularExpressions;
using AcShadow.Analysis.Doctor;
using AcShadow.Core.Dat;
using AcShadow.Fixtures.Formats;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Doctor;

/// <summary>`acshadow doctor` as a user runs it, and what its report may and may not hold.</summary>
public sealed class DoctorCommandTests
{
    [Fact]
    public void Doctor_on_the_sample_prints_a_verdict_per_check_and_writes_the_json_report()
    {
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "doctor.json");

        var run = CliRun.Of("doctor", "--out", file, "--jobs", "2");

        Assert.Equal(0, run.ExitCode);
        using var doc = JsonDocument.Parse(File.ReadAllText(file));
        Assert.Equal(FileFormats.Doctor.Format, doc.RootElement.GetProperty("format").GetString());
        var checks = doc.RootElement.GetProperty("checks").EnumerateArray().ToArray();
        Assert.True(checks.Length >= 14);
        foreach (var check in checks)
            Assert.Matches($@"(?m)^  {Regex.Escape(check.GetProperty("verdict").GetString()!)} +{Regex.Escape(check.GetProperty("key").GetString()!)} ", run.Out);
        var determinism = checks.Single(c => c.GetProperty("key").GetString() == "tool.determinism");
        Assert.Equal("holds", determinism.GetProperty("verdict").GetString());
        Assert.Equal(determinism.GetProperty("sha256").GetProperty("firstRun").GetString(), determinism.GetProperty("sha256").GetProperty("secondRun").GetString());
        Assert.True(determinism.GetProperty("measured").GetProperty("peakMemoryMiB").GetDouble() > 0);
        // One screen: the summary fits in 40 lines.
        Assert.InRange(run.Out.Split('\n').Length, 10, 40);
    }

    [Fact]
    public void The_report_is_the_same_for_any_job_count_but_for_what_it_measures()
    {
        var one = Normalised(ReportJson(jobs: 1));
        var two = Normalised(ReportJson(jobs: 2));
        Assert.Equal(one, two);
    }

    /// <summary>
    /// Ids, counts, hashes, verdicts and fixed text only: every number outside "measured" is an integer, every
    /// string is an id, a hash, or text that reads the same on another dat, and no coordinate, plane value or
    /// radius of the dat's GfxObjs appears anywhere in it.
    /// </summary>
    [Fact]
    public void The_report_holds_no_geometry_names_or_dat_bytes()
    {
        var json = ReportJson(jobs: 2);
        using var doc = JsonDocument.Parse(json);
        var strings = new List<(string Path, string Value)>();
        Walk(doc.RootElement, "", strings);
        foreach (var (path, value) in strings)
        {
            var allowed = Regex.IsMatch(value, "^0x[0-9A-F]{8}$")
                || path.EndsWith("/sha256/firstRun") || path.EndsWith("/sha256/secondRun")
                || path.EndsWith("/claim") || path.EndsWith("/headline")
                || path is "/format" or "/toolVersion" or "/dat/kind" or "/cellDat/kind"
                || Regex.IsMatch(path, "^/checks/[0-9]+/(key|section|verdict|exampleKind)$");
            Assert.True(allowed, $"{path}: a string the report may not hold");
            if (path.EndsWith("/sha256/firstRun") || path.EndsWith("/sha256/secondRun")) Assert.Matches("^[0-9a-f]{64}$", value);
        }
        // Claims are fixed text: the same on another dat (here: the sample without its GfxObjs).
        var other = DoctorDats.Report(DoctorDats.Portal(DoctorDats.SampleObjects().Where(o => !DatObjectKind.GfxObj.Contains(o.Key)).ToDictionary()));
        Assert.Equal(other.Checks.Select(c => c.Claim), doc.RootElement.GetProperty("checks").EnumerateArray().Select(c => c.GetProperty("claim").GetString()));
        // Headlines carry whole numbers only, but for the tool's own timing.
        foreach (var check in doc.RootElement.GetProperty("checks").EnumerateArray().Where(c => c.GetProperty("key").GetString() != "tool.determinism"))
            Assert.DoesNotMatch(@"\d\.\d", check.GetProperty("headline").GetString()!);

        var geometry = new HashSet<string>(StringComparer.Ordinal);
        using var sample = SampleDat.OpenPortal();
        foreach (var id in sample.ListIds(DatObjectKind.GfxObj))
        {
            var gfx = sample.ReadGfxObj(id)!;
            foreach (var v in gfx.Vertices.Values) Add(v.X, v.Y, v.Z);
            if (gfx.PhysicsBsp is { } root)
                foreach (var node in DoctorDats.Nodes(root))
                    Add(node.SplittingPlane.Normal.X, node.SplittingPlane.Normal.Y, node.SplittingPlane.Normal.Z, node.SplittingPlane.D,
                        node.BoundingSphere.Center.X, node.BoundingSphere.Center.Y, node.BoundingSphere.Center.Z, node.BoundingSphere.Radius);
        }
        Assert.NotEmpty(geometry);
        // What this machine measured (seconds, MiB) may equal a coordinate by chance: it is not the dat's.
        var numbers = Regex.Matches(Normalised(json), @"-?\d+\.\d+(?:[eE][-+]?\d+)?").Select(m => m.Value).ToArray();
        Assert.DoesNotContain(numbers, geometry.Contains);
        foreach (var number in NumbersOutsideMeasured(doc.RootElement, ""))
            Assert.True(number.ValueKind == JsonValueKind.Number && number.TryGetInt64(out _), $"{number}: not a whole number");

        void Add(params float[] values)
        {
            // Whole numbers (0, 1, -1 …) are counts too; only fractions betray geometry.
            foreach (var f in values)
                if (float.IsFinite(f) && f != MathF.Round(f)) geometry.Add(f.ToString("R", CultureInfo.InvariantCulture));
        }
    }

    [Fact]
    public void A_folder_for_out_is_refused_with_the_output_exit_code()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("doctor", "--out", dir.Path);
        Assert.Equal(6, run.ExitCode);
        Assert.Contains("is a folder", run.Error);
    }

    private static string ReportJson(int jobs)
    {
        using var portal = DatArchive.Open(new MemoryStream(SampleDat.PortalBytes, writable: false), "client_portal.dat");
        using var cell = DatArchive.Open(new MemoryStream(SampleDat.CellBytes!, writable: false), "client_cell_1.dat");
        var report = DoctorRunner.Run(portal, cell, new DoctorOptions(jobs, "test", () => 100L << 20));
        return System.Text.Encoding.UTF8.GetString(DoctorReportWriter.Json(report));
    }

    /// <summary>The report without the figures measured on this machine (and the headline that quotes one).</summary>
    private static string Normalised(string json)
    {
        json = Regex.Replace(json, "\"measured\": \\{[^}]*\\}", "\"measured\": {}");
        return Regex.Replace(json, "\"headline\": \"same bytes twice[^\"]*\"", "\"headline\": \"\"");
    }

    private static void Walk(JsonElement e, string path, List<(string, string)> strings)
    {
        switch (e.ValueKind)
        {
            case JsonValueKind.Object:
                foreach (var p in e.EnumerateObject()) Walk(p.Value, $"{path}/{p.Name}", strings);
                break;
            case JsonValueKind.Array:
                var i = 0;
                foreach (var item in e.EnumerateArray()) Walk(item, $"{path}/{i++}", strings);
                break;
            case JsonValueKind.String:
                strings.Add((path, e.GetString()!));
                break;
        }
    }

    private static IEnumerable<JsonElement> NumbersOutsideMeasured(JsonElement e, string path)
    {
        switch (e.ValueKind)
        {
            case JsonValueKind.Object:
                foreach (var p in e.EnumerateObject().Where(p => p.Name != "measured"))
                    foreach (var n in NumbersOutsideMeasured(p.Value, $"{path}/{p.Name}")) yield return n;
                break;
            case JsonValueKind.Array:
                foreach (var item in e.EnumerateArray())
                    foreach (var n in NumbersOutsideMeasured(item, path)) yield return n;
                break;
            case JsonValueKind.Number:
                yield return e;
                break;
        }
    }
}
