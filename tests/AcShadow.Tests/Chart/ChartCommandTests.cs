using AcShadow.Analysis.Chart.Cells;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart;

public class ChartCommandTests
{
    [Fact]
    public void Chart_on_the_sample_door_writes_every_file_and_a_summary()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--setup", "0x020019FF", "--out", dir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(["chart.csv", "failure-map-0x020019FF.svg", "failures.csv", "speed-accuracy.svg", "summary.csv"], dir.Files());
        Assert.Contains("fallback-cylinder", run.Out);
        Assert.Contains("0x020019FF: cheapest exact model", run.Out);
    }

    [Fact]
    public void Several_setups_and_a_smaller_probe_are_accepted()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--setup", "0x020019FF", "--setup", "0x02001000", "--probe-radius", "0.3", "--spacing", "0.5", "--out", dir.Path, "--quiet");
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("failure-map-0x02001000.svg", dir.Files());
        Assert.Contains("radius 0.3 m, spacing 0.5 m", run.Out);
    }

    [Fact]
    public void A_landblock_charts_the_setups_and_bare_gfxobjs_it_places()
    {
        // The sample landblock places the door and the multi-part static (Setups), a bare column and the
        // house (GfxObjs), and a Setup inside the cottage's ground-floor cell: the same selection batch exports.
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--landblock", "0xA9B4", "--spacing", "1", "--out", dir.Path, "--quiet");
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("5 object(s) (3 Setup(s), 2 bare GfxObj(s))", run.Out);
        foreach (var id in new[] { "0x020019FF", "0x02003000", "0x02003300", "0x01003002", "0x01005000" })
        {
            Assert.Contains($"failure-map-{id}.svg", dir.Files());
            var rows = File.ReadAllLines(Path.Combine(dir.Path, "chart.csv")).Count(l => l.StartsWith(id + ",", StringComparison.Ordinal));
            Assert.Equal(AcShadow.Analysis.Chart.Models.ShapeModels.All.Count, rows);
        }
    }

    [Fact]
    public void A_landblock_chart_probes_its_indoor_cells_as_retail_and_no_cells_leaves_them_out()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--landblock", "0xA9B4", "--spacing", "1", "--out", dir.Path, "--quiet");
        Assert.True(run.ExitCode == 0, run.Error);
        Assert.Contains("2 indoor cell(s) probed as retail", run.Out);
        var rows = File.ReadAllLines(Path.Combine(dir.Path, AcShadow.Analysis.Chart.Cells.CellsCsv.FileName));
        Assert.Equal(AcShadow.Analysis.Chart.Cells.CellsCsv.Header, rows[0]);
        var header = rows[0].Split(',');
        int Column(string name) => Array.IndexOf(header, name);
        Assert.Equal(["0xA9B40100", "0xA9B40101"], rows.Skip(1).Select(r => r.Split(',')[0]));
        foreach (var row in rows.Skip(1).Select(r => r.Split(',')))
        {
            // The walls are probed on both sides of where a mover starts touching them, and retail's tree answers.
            Assert.Equal("retail", row[Column("model")]);
            Assert.True(int.Parse(row[Column("face_probes")]) > 0, string.Join(',', row));
            Assert.True(int.Parse(row[Column("blocked")]) > 0, string.Join(',', row));
            Assert.True(int.Parse(row[Column("clear")]) > 0, string.Join(',', row));
            Assert.Equal(int.Parse(row[Column("probes")]), int.Parse(row[Column("blocked")]) + int.Parse(row[Column("clear")]));
        }

        using var objectsOnly = new TempDir();
        run = CliRun.Of("chart", "--landblock", "0xA9B4", "--no-cells", "--spacing", "1", "--out", objectsOnly.Path, "--quiet");
        Assert.True(run.ExitCode == 0, run.Error);
        Assert.DoesNotContain(AcShadow.Analysis.Chart.Cells.CellsCsv.FileName, objectsOnly.Files());
        Assert.DoesNotContain("indoor cell", run.Out);
    }

    [Theory]
    [InlineData(2, "choose what to chart", "chart", "--out", "x")]
    [InlineData(2, "'0xZZ' is not a landblock", "chart", "--landblock", "0xZZ", "--out", "x")]
    [InlineData(4, "has no LandBlockInfo (0x0101FFFE)", "chart", "--landblock", "0x0101", "--out", "x")]
    [InlineData(2, "--probe-radius: '-1' is not a positive number", "chart", "--setup", "0x020019FF", "--probe-radius", "-1", "--out", "x")]
    [InlineData(2, "--spacing: 'abc'", "chart", "--setup", "0x020019FF", "--spacing", "abc", "--out", "x")]
    [InlineData(2, "spacing must be at least 0.01 m", "chart", "--setup", "0x020019FF", "--spacing", "0.001", "--out", "x")]
    [InlineData(4, "Setup 0x0200ABCD is not in", "chart", "--setup", "0x0200ABCD", "--out", "x")]
    [InlineData(2, "--no-cells applies to a landblock's scene", "chart", "--setup", "0x020019FF", "--no-cells", "--out", "x")]
    [InlineData(2, "--mover and --walk apply to --movement", "chart", "--setup", "0x020019FF", "--walk", "closed/out-in/lat+0.450/hdg+00/walk", "--out", "x")]
    [InlineData(4, "--mover: Setup 0x0200ABCD is not in", "chart", "--setup", "0x020019FF", "--movement", "--mover", "0x0200ABCD", "--out", "x")]
    public void Usage_and_missing_setups_are_one_line_errors(int code, string message, params string[] args)
    {
        var run = CliRun.Of(args);
        Assert.Equal(code, run.ExitCode);
        Assert.Contains(message, run.Error);
    }

    [Fact]
    public void Chart_movement_writes_the_movement_files_and_they_are_the_same_at_one_and_two_jobs_but_for_the_time_column()
    {
        using var one = new TempDir();
        using var two = new TempDir();
        foreach (var (dir, jobs) in new[] { (one, "1"), (two, "2") })
        {
            var run = CliRun.Of("chart", "--setup", "0x020019FF", "--setup", "0x02001000", "--spacing", "1", "--movement", "--jobs", jobs, "--out", dir.Path, "--quiet");
            Assert.True(run.ExitCode == 0, run.Error);
            Assert.Contains("movement: 840 walk(s) per model", run.Out);
        }
        foreach (var name in new[] { "movement-chart.csv", "movement-summary.csv" })
        {
            // Everything but the last column (ns_per_transition, a measurement).
            static string[] Masked(string path) => [.. File.ReadAllLines(path).Select(l => l[..l.LastIndexOf(',')])];
            Assert.Equal(Masked(Path.Combine(one.Path, name)), Masked(Path.Combine(two.Path, name)));
        }
        foreach (var name in new[] { "movement-map-0x020019FF.svg", "movement-map-0x02001000.svg" })
            Assert.Equal(File.ReadAllBytes(Path.Combine(one.Path, name)), File.ReadAllBytes(Path.Combine(two.Path, name)));
        var fallback = File.ReadAllLines(Path.Combine(one.Path, "movement-chart.csv")).Single(l => l.StartsWith("0x020019FF,fallback-cylinder,", StringComparison.Ordinal));
        Assert.NotEqual("0", fallback.Split(',')[5]);

        using var unknown = new TempDir();
        var walk = CliRun.Of("chart", "--setup", "0x020019FF", "--spacing", "1", "--movement", "--walk", "closed/nowhere", "--out", unknown.Path, "--quiet");
        Assert.True(walk.ExitCode == 0, walk.Error);
        Assert.Contains("warning: --walk closed/nowhere: no charted object has that case", walk.Error);
        Assert.DoesNotContain(unknown.Files(), f => f.StartsWith("movement-walk-", StringComparison.Ordinal));
    }
}
