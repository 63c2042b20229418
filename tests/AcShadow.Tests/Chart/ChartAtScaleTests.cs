using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Errors;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart;

/// <summary>
/// docs/chart.md, "charting a whole dat" and docs/errors.md, "absurd inputs": results stream out object by
/// object in order (whatever --jobs), the probe grid stays bounded however large the object, absurd
/// scales are refused, and long id lists are summarised.
/// </summary>
public class ChartAtScaleTests
{
    private static readonly uint[] Setups = [0x020019FF, 0x02001000, 0x02002000];

    [Fact]
    public void Streamed_charts_arrive_in_order_one_by_one_and_match_the_whole_report_with_any_job_count()
    {
        var whole = SampleChart.Run(null, Setups);
        foreach (var jobs in new[] { 1, 2, 3 })
        {
            var arrived = new List<(uint Id, int DoneBefore)>();
            var done = 0;
            var rows = new System.Text.StringBuilder();
            var tally = ChartRunner.Stream(Setups.Length, i => SampleChart.Subjects.Value.For(Setups[i]), new ChartOptions(), chart =>
            {
                arrived.Add((chart.SetupId, done));
                rows.Append(ChartCsv.Rows(chart));
            }, timer: new FixedTimer(), progress: (d, _) => done = d, jobs: jobs);

            Assert.Equal(Setups, arrived.Select(a => a.Id));
            // Each object is handed over before the next is counted done: nothing waits for the end.
            Assert.Equal([0, 1, 2], arrived.Select(a => a.DoneBefore));
            Assert.Equal(whole.Text("chart.csv"), ChartCsv.Header + "\n" + rows);
            Assert.Equal(whole.Text("summary.csv"), SummaryCsv.Write(tally.Summaries()));
        }
    }

    [Fact]
    public void A_chart_of_many_warned_objects_prints_the_first_ten_objects_warnings_and_counts_every_warning_by_code()
    {
        // Fourteen Setups whose HasPhysicsBSP flag is clear over a part with a BSP (a flag-mismatch warning each),
        // and the healthy one: a whole dat's chart would print thousands of such lines.
        var ids = Enumerable.Range(0, 14).Select(i => 0x02000100u + (uint)i).ToArray();
        using var dat = BrokenDats.Folder(BrokenDats.Portal(
            [.. ids.Select(id => BrokenDats.Bytes(BrokenDats.SetupOf(id, BrokenDats.HealthyGfxObj) with { Flags = default }))]));
        using var dir = new TempDir();

        var run = CliRun.Of("chart", "--all", "--dat", dat.Path, "--out", dir.Path, "--quiet");

        Assert.Equal(0, run.ExitCode);
        var warned = run.ErrorLines.Where(l => l.StartsWith("warning: 0x", StringComparison.Ordinal)).ToArray();
        var perObject = warned.Length / 10;
        Assert.Equal(10 * perObject, warned.Length);
        Assert.True(perObject >= 1, run.Error);
        Assert.All(warned, l => Assert.Contains(": flag-mismatch: ", l));
        Assert.Equal(10, warned.Select(l => l.Split(':')[1]).Distinct().Count());
        Assert.Single(run.ErrorLines, l => l.StartsWith("warning: more objects have warnings; only the first 10 objects' are shown", StringComparison.Ordinal));
        // The summary counts all fourteen objects' warnings, the ten shown and the four not.
        Assert.Contains($"  {14 * perObject} warning(s) in 14 object(s): flag-mismatch {14 * perObject} (the first 10 objects' in full on stderr)", run.Out.Split('\n'));
    }

    [Fact]
    public void The_grid_stays_under_its_probe_limit_however_large_the_object()
    {
        var options = new ChartOptions();
        var huge = new Bounds(new Vector3(-1e30f), new Vector3(1e30f));
        var grid = ProbeGrid.Build(huge, options);
        Assert.InRange(grid.Probes.Count, 1, options.MaxGridProbes);
        Assert.True(grid.Spacing > options.Spacing);
    }

    [Theory]
    [InlineData("1e30")]
    [InlineData("1e5")]
    [InlineData("1e-45")]
    public void Absurd_scales_are_refused_with_a_usage_error(string scale)
    {
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--setup", "0x020019FF", "--scale", scale, "--out", dir.Path, "--quiet");
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--scale: {scale} is outside 0.001-1000", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
        Assert.Empty(dir.Files());
    }

    [Fact]
    public void Plain_progress_lines_name_the_command_that_runs()
    {
        var error = new StringWriter();
        var progress = new ProgressReporter(error, isTerminal: false, quiet: false, "objects charted", "chart");
        Thread.Sleep(TimeSpan.FromSeconds(2.2)); // plain lines come every 2 s at most
        progress.Report(new BatchProgress(3, 10));
        Assert.StartsWith("chart: 3/10 objects charted", error.ToString());
    }

    [Fact]
    public void Skipped_ids_are_summarised_not_listed_in_one_enormous_line()
    {
        using var dir = new TempDir();
        var list = Path.Combine(dir.Path, "ids.txt");
        File.WriteAllLines(list, Enumerable.Range(0xF000, 30).Select(i => $"0x0200{i:X4}"));

        var run = CliRun.Of("batch", "--setups", list, "--out", Path.Combine(dir.Path, "out"), "--quiet");

        Assert.Equal(0, run.ExitCode);
        var line = Assert.Single(run.Out.Split('\n'), l => l.Contains("skipped 30"));
        Assert.Contains("0x0200F000", line);
        Assert.Contains("… and 20 more (all in index.json's skipped)", line);
        Assert.DoesNotContain("0x0200F01D", line);
    }

    [Fact]
    public void A_BSP_sphere_a_flipped_exponent_bit_sends_1e38_m_away_charts_with_the_coarsening_said_and_a_map_of_bounded_size()
    {
        // The part's bounding sphere as a fuzzed dat damaged it (seed 1, case 3833): one exponent bit of its
        // centre's y flipped, 0.7 m becoming 2.4e38 m. The part-spheres model then sees a sphere there, so the
        // grid spans 1e38 m (coarsened to fit its probe limit) and lies in one layer, which the map draws.
        var y = BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(0.7f) ^ (1 << 30));
        Assert.True(y > 1e38f);
        var leaf = new PhysicsBspNode(BspNodeType.Leaf, default, null, null,
            new Sphere(new Vector3(0.5f, y, 0.3f), 0.77f), 0, 1, [0]);
        using var dat = BrokenDats.Folder(BrokenDats.Portal(
            BrokenDats.Bytes(BrokenDats.SetupOf(0x02000002, 0x01000002)), BrokenDats.Bytes(BrokenDats.Box(0x01000002, bsp: leaf))));
        using var dir = new TempDir();

        var allocated = GC.GetAllocatedBytesForCurrentThread();
        var run = CliRun.Of("chart", "--setup", "0x02000002", "--dat", dat.Path, "--out", dir.Path, "--quiet");
        allocated = GC.GetAllocatedBytesForCurrentThread() - allocated;

        Assert.Equal(0, run.ExitCode);
        // Not a silent guess: the coarsening is a warning naming the span that forced it.
        var warning = Assert.Single(run.ErrorLines, l => l.StartsWith("warning: 0x02000002: grid-coarsened: ", StringComparison.Ordinal));
        Assert.Matches(@"the shapes span [^ ]+ × 2\.\d+E\+38 × [^ ]+ m$", warning);
        var map = Path.Combine(dir.Path, "failure-map-0x02000002.svg");
        var cells = System.Xml.Linq.XDocument.Load(map).Descendants().Count(e => e.Name.LocalName == "rect");
        var models = Analysis.Chart.Models.ShapeModels.All.Count;
        Assert.InRange(cells, models, models * (FailureMapSvg.MaxCellsPerSide * FailureMapSvg.MaxCellsPerSide + 1) + 4);
        Assert.Contains("per cell (worst verdict shown", File.ReadAllText(map));
        // The fuzz campaign's bound for a whole case; before the map merged cells, this chart alone took 403 MiB.
        Assert.True(allocated < 128L << 20, $"allocated {allocated >> 20} MiB");
    }

    [Fact]
    public void A_part_with_a_vertex_ten_million_km_away_charts_in_bounded_memory()
    {
        // Fuzz seed 1, case 36265: bit flips sent one vertex of a part 1.7e10 m away. Its face lattice was
        // sized by squaring an int that overflowed there, so stability probes were laid without end (14 GB
        // within 24 s, then the kernel's OOM killer). Here a triangle's corner goes as far, in its own plane: one
        // triangle's lattice, miscounted, wraps the probe count negative, so nothing was coarsened either.
        using var dat = BrokenDats.Folder(BrokenDats.Portal(
            BrokenDats.Bytes(BrokenDats.SetupOf(0x02000002, 0x01000002)),
            BrokenDats.Bytes(BrokenDats.Box(0x01000002, v => { v[2] = new Vector3(0.5f, 1.7e10f, 0); return v; }, polygonVertices: [0, 1, 2]))));
        using var dir = new TempDir();

        var allocated = GC.GetAllocatedBytesForCurrentThread();
        var run = CliRun.Of("chart", "--setup", "0x02000002", "--dat", dat.Path, "--out", dir.Path, "--quiet");
        allocated = GC.GetAllocatedBytesForCurrentThread() - allocated;

        Assert.True(run.ExitCode == 0, run.Out + run.Error);
        Assert.True(allocated < 128L << 20, $"allocated {allocated >> 20} MiB");
    }

    [Fact]
    public void A_failure_map_wider_than_its_cell_limit_merges_cells_and_a_false_pass_is_never_merged_away()
    {
        // A flat 201 × 201 layer (40,401 grid probes), all clear, but for one false pass and one false block.
        var options = new ChartOptions { Spacing = 1f, Margin = 0f };
        var probes = ProbeGrid.Build(new Bounds(new Vector3(-100, -100, 0), new Vector3(100, 100, 0)), options).Probes.ToArray();
        Assert.Equal(201 * 201, probes.Length);
        var pass = Array.FindIndex(probes, p => p.Center.X == 37 && p.Center.Y == -12);
        var block = Array.FindIndex(probes, p => p.Center.X == -80 && p.Center.Y == 55);
        var reference = new bool[probes.Length];
        reference[pass] = true;
        var answers = new bool[probes.Length];
        answers[block] = true;
        var timing = TimingStats.Of([1.0]);
        ModelOutcome Outcome(string name, bool[] a, int falsePass, int falseBlock) =>
            new(name, 1, a, probes.Length - falsePass - falseBlock, falsePass, falseBlock, 0, 0, 0, timing, [], []);
        var chart = new ObjectChart(0x02000001, probes, 1f, new Bounds(new Vector3(-100), new Vector3(100)), null, reference,
            [Outcome("retail", reference, 0, 0), Outcome("model", answers, 1, 1)], "retail", []);

        var svg = FailureMapSvg.Write(options, "retail", chart);

        // 201 cells a side is merged 3 × 3 into 67 a side, and every verdict that was there is still drawn.
        Assert.Contains("3 × 3 per cell", svg);
        var fills = System.Xml.Linq.XDocument.Parse(svg).Descendants().Where(e => e.Name.LocalName == "rect")
            .Select(e => (string?)e.Attribute("fill")).ToArray();
        // Each row's neighbouring cells of one verdict are one rectangle: 67 rows a panel, and a row holding a
        // lone verdict is three runs (clear, it, clear). Reference: one such row; model: two. Plus the legend's
        // four swatches, the two panels' frames and the page's background.
        Assert.Equal(67 + 2 + (67 + 4) + 4 + 2 + 1, fills.Length);
        Assert.Equal(1 + 1, fills.Count(f => f == "#d62728"));    // the model's merged false pass, and the legend's swatch
        Assert.Equal(1 + 1, fills.Count(f => f == "#1f77b4"));    // its false block, and the legend's
        Assert.Equal(1 + 1, fills.Count(f => f == "#5a5a5a"));    // the reference blocking in its own panel, and the legend's
    }
}
