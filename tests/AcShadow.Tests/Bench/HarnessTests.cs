using System.Text.Json;
using AcShadow.Bench.Harness;
using AcShadow.Forge.Scale;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Bench;

/// <summary>
/// The benchmark harness at a tiny scale, against the CLI this test run built: it runs end to end and
/// bench.json carries every figure, ratio and check. Its timings are not asserted (speed is measured by
/// scripts/bench.sh, never by a test).
/// </summary>
[Trait("Speed", "Slow")]
public sealed class HarnessTests
{
    private static readonly string[] Measured = ["floor", "batch", "batch --incremental", "doctor"];

    [Fact]
    public void A_tiny_harness_run_writes_every_figure_to_bench_json()
    {
        using var dir = new TempDir();
        const int setups = 60; // at least the 58 door ids, so the door dump has its Setup
        var options = new HarnessOptions(setups, ScaleSpecGenerator.GfxObjsFor(setups), 3, 1, 1,
            Path.Combine(AppContext.BaseDirectory, "acshadow.dll"), Path.Combine(dir.Path, "cache"), Path.Combine(dir.Path, "work"),
            Path.Combine(dir.Path, "memory-work"), Path.Combine(dir.Path, "bench.json"), true)
        {
            // The built tool stands in for what `dotnet tool install` puts on the PATH (scripts/bench.sh installs the packed tool).
            InstalledCli = Path.Combine(AppContext.BaseDirectory, "acshadow.dll"),
        };
        var log = new StringWriter();

        var report = BenchHarness.Run(options, log);

        Assert.All(report.Checks, c => Assert.True(c.Passed, $"{c.Name}: {string.Join("; ", c.Problems)}"));
        using var json = JsonDocument.Parse(File.ReadAllBytes(options.Output));
        var root = json.RootElement;
        Assert.Equal(BenchReport.Format, root.GetProperty("format").GetString());
        Assert.True(root.GetProperty("machine").GetProperty("cores").GetInt32() >= 1);
        foreach (var size in new[] { "full", "quarter", BenchReport.ScalingSize })
            Assert.True(root.GetProperty("dats").GetProperty(size).GetProperty("portalBytes").GetInt64() > 0);
        Assert.True(root.GetProperty("machine").GetProperty("loadAverageAtEnd").GetDouble() >= 0);
        // Each core's speed at the start and the end, one pinned loop each (Linux: sched_setaffinity).
        foreach (var when in new[] { "coreLoopMsAtStart", "coreLoopMsAtEnd" })
        {
            var loops = root.GetProperty("machine").GetProperty(when).EnumerateArray().Select(e => e.GetDouble()).ToArray();
            if (OperatingSystem.IsLinux()) Assert.Equal(Math.Min(Environment.ProcessorCount, 64), loops.Length);
            Assert.All(loops, ms => Assert.True(ms > 0, $"{when}: {ms} ms"));
        }
        Assert.Contains("Core speeds (one fixed loop pinned to each core, ms)", log.ToString());

        var timings = root.GetProperty("timings").EnumerateArray().ToArray();
        foreach (var name in Measured)
            foreach (var size in new[] { "full", "quarter" })
                Assert.Contains(timings, t => t.GetProperty("name").GetString() == name && t.GetProperty("size").GetString() == size);
        // Batch runs on both places, on the scaling dat too; the floor writes nothing.
        foreach (var output in new[] { "disk", "memory" })
            foreach (var size in new[] { "full", "quarter", BenchReport.ScalingSize })
                Assert.Contains(timings, t => t.GetProperty("name").GetString() == "batch" && t.GetProperty("size").GetString() == size && t.GetProperty("output").GetString() == output);
        Assert.All(timings.Where(t => t.GetProperty("name").GetString() == "floor"), t => Assert.Equal("none", t.GetProperty("output").GetString()));
        // The everyday re-run into the last run's folder is timed on disk only.
        Assert.All(timings.Where(t => t.GetProperty("name").GetString() == "batch, again into its output"),
            t => Assert.Equal("disk", t.GetProperty("output").GetString()));
        Assert.Equal(2, timings.Count(t => t.GetProperty("name").GetString() == "batch, again into its output"));
        // Every run's output folder (one per disk run) is gone when the harness ends.
        Assert.False(Directory.Exists(options.WorkDirectory) && Directory.EnumerateFileSystemEntries(options.WorkDirectory).Any());
        Assert.Contains(timings, t => t.GetProperty("name").GetString() == "dump --setup");
        Assert.Contains(timings, t => t.GetProperty("name").GetString() == "dump --setup, new folder");
        Assert.Contains(timings, t => t.GetProperty("name").GetString() == "acshadow --version");
        Assert.Contains(timings, t => t.GetProperty("name").GetString() == BenchReport.InstalledVersion);
        Assert.Contains(timings, t => t.GetProperty("name").GetString() == BenchReport.InstalledDump);
        Assert.All(timings, t =>
        {
            Assert.True(t.GetProperty("medianSeconds").GetDouble() > 0, t.ToString());
            Assert.True(t.GetProperty("peakMiB").GetDouble() > 0, t.ToString());
        });

        var collision = root.GetProperty("collision");
        Assert.True(collision.GetProperty("queries").GetInt32() > 0);
        Assert.Equal(0, collision.GetProperty("disagreements").GetInt32());
        Assert.True(collision.GetProperty("minPolygons").GetInt32() >= CollisionComparison.MinPolygons);

        var ratios = root.GetProperty("ratios").EnumerateArray().ToArray();
        Assert.Equal(report.Ratios.Select(r => r.Name), ratios.Select(r => r.GetProperty("name").GetString()));
        // Two scaling targets (the scale dat, the scaling dat) on each of disk and memory, eleven others (two the
        // doctor's, scene against chart, the scene's peak memory), the installed tool's start-up, and compiled against
        // all-retail and the partition against the exhaustive walk per mover position, timed and counted, on the
        // scale landblock and the sample.
        Assert.Equal(24, ratios.Length);
        Assert.DoesNotContain(ratios, r => r.GetProperty("name").GetString()!.StartsWith("naive", StringComparison.Ordinal));
        Assert.Contains(ratios, r => r.GetProperty("name").GetString() == "dump / --version, installed tool");
        Assert.Contains(ratios, r => r.GetProperty("name").GetString() == "peak MiB, scene --landblock (full)");
        Assert.Equal(4, ratios.Count(r => r.GetProperty("name").GetString()!.Contains(": compiled / all-retail, ", StringComparison.Ordinal)));
        Assert.Equal(4, ratios.Count(r => r.GetProperty("name").GetString()!.Contains(": all-retail partitioned / exhaustive, ", StringComparison.Ordinal)));
        Assert.Contains(ratios, r => r.GetProperty("name").GetString()!.EndsWith("(memory)", StringComparison.Ordinal));
        Assert.All(ratios, r => Assert.True(r.GetProperty("value").GetDouble() > 0, r.ToString()));
        Assert.Contains("| Target | Measured | Goal | Met |", log.ToString());
        Assert.Contains("load average", log.ToString());
        Assert.False(Directory.Exists(options.WorkDirectory), "the harness leaves no output folders behind");
        Assert.False(Directory.Exists(options.MemoryWorkDirectory), "nor in its memory-backed work folder");
    }

    [Fact]
    public void A_run_limited_to_start_up_times_only_start_up_and_reports_only_its_ratios()
    {
        using var dir = new TempDir();
        const int setups = 60;
        var options = HarnessOptions.Parse(["--cli", Path.Combine(AppContext.BaseDirectory, "acshadow.dll"), "--small", "--setups", "60",
            "--cache", Path.Combine(dir.Path, "cache"), "--work", Path.Combine(dir.Path, "work"), "--memory-work", "none",
            "--out", Path.Combine(dir.Path, "bench.json"), "--only", "startup"]);
        Assert.Equal(setups, options.Setups);
        var log = new StringWriter();

        var report = BenchHarness.Run(options, log);

        Assert.Equal(["acshadow --version", "dump --setup", "dump --setup, new folder"], report.Timings.Select(t => t.Name));
        // The start-up ratios and the in-process collision check; nothing built on a workload that did not run.
        Assert.Equal(["dump / --version", "dump into a new folder / --version", "brute force / reference"], report.Ratios.Select(r => r.Name));
        using var json = JsonDocument.Parse(File.ReadAllBytes(options.Output));
        Assert.Equal("startup", json.RootElement.GetProperty("parameters").GetProperty("only").GetString());
        Assert.Contains("Workloads: startup.", log.ToString());
    }

    [Fact]
    public void Only_takes_known_groups_and_names_them_when_given_another()
    {
        string[] args = ["--cli", "acshadow", "--only"];
        var both = HarnessOptions.Parse([.. args, "scaling, landblock"]);
        Assert.True(both.Runs("scaling") && both.Runs("landblock"));
        Assert.False(both.Runs("export") || both.Runs("chart-all") || both.Runs("startup") || both.Runs("cells"));
        Assert.All(HarnessOptions.Groups, g => Assert.True(HarnessOptions.Parse(["--cli", "acshadow"]).Runs(g)));
        var error = Assert.Throws<ArgumentException>(() => HarnessOptions.Parse([.. args, "scene"]));
        Assert.Contains("export, scaling, chart-all, startup, landblock, cells", error.Message);
        Assert.Contains("\"scene\"", error.Message);
    }
}
