using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>
/// One harness run: forge (or reuse) the scale dat, its quarter-size twin and the 3,000-Setup scaling dat, then
/// measure side by side, each warmed once and repeated: the floor, `batch --all` at one job and at all cores
/// (on all three dats), `--incremental` with nothing to do, `doctor`, `dump` against `--version` (the published
/// binary, and what `dotnet tool install` put on the PATH), the busiest landblock's scene with and without its
/// indoor cells, `scene` against `chart` on the scale dat's busy landblock (with the scene's peak memory), and the
/// collision reference against brute force; check the outputs are byte-identical; write bench.json and print the table.
/// </summary>
public static class BenchHarness
{
    public const string DoorSetup = "0x020019FF";

    /// <summary>The scale dat's busy landblock (<see cref="AcShadow.Forge.Scale.ScaleSpecGenerator.BusyLandblockObjects"/> objects).</summary>
    public const string BusyLandblock = "0x0000";

    /// <summary>The built-in sample's landblock, compiled once for its scene chart.</summary>
    public const string SampleLandblock = "0xA9B4";

    public static BenchReport Run(HarnessOptions options, TextWriter log)
    {
        var started = DateTime.UtcNow;
        var machine = MachineInfo.Current();
        var cores = Environment.ProcessorCount;
        foreach (var (_, root) in OutputPlaces(options)) Directory.CreateDirectory(root);
        var full = ScaleDatCache.Get(options.CacheDirectory, options.Setups, options.GfxObjs, options.Seed, log);
        var quarter = ScaleDatCache.Get(options.CacheDirectory, Math.Max(1, options.Setups / 4),
            Math.Max(AcShadow.Forge.Scale.ScaleSpecGenerator.MinGfxObjs(Math.Max(1, options.Setups / 4)), options.GfxObjs / 4), options.Seed, log);
        var scaling = options.Small
            ? ScaleDatCache.Get(options.CacheDirectory, HarnessOptions.SmallScalingSetups, AcShadow.Forge.Scale.ScaleSpecGenerator.GfxObjsFor(HarnessOptions.SmallScalingSetups), HarnessOptions.ScalingSeed, log)
            : ScaleDatCache.Get(options.CacheDirectory, HarnessOptions.ScalingSetups, HarnessOptions.ScalingGfxObjs, HarnessOptions.ScalingSeed, log);

        var timings = new List<Timing>();
        var checks = new List<Check>();
        var extraRatios = new List<Ratio>();
        try
        {
            var jobCounts = cores > 1 ? new[] { 1, cores } : [1];
            // batch --all at every job count into empty folders of the place, and the check that their outputs are the same bytes.
            // The job counts take turns run by run: whatever drifts while they run (the write-back of what an earlier
            // workload wrote, the virtual machine's memory backing) then falls on both sides of the ratio alike.
            Dictionary<int, string> Batches(string size, string dat, CachedDat forged, string output, RunFolders place)
            {
                var outputs = new Dictionary<int, string>();
                timings.AddRange(MeasureInterleaved(log, options, "batch", size, jobCounts, output, jobs => $"acshadow batch --all --jobs {jobs} --quiet into an empty folder ({forged.Setups} Setups)",
                    (jobs, run) => ProcessRunner.Run(options.Cli, ["batch", "--all", "--dat", forged.Directory, "--out", outputs[jobs] = place.Empty($"batch-{size}-j{jobs}", run), "--jobs", Text(jobs), "--quiet"])));
                if (cores > 1)
                    checks.Add(new Check($"batch output byte-identical, --jobs 1 vs --jobs {cores} ({dat}, {output})", OutputComparison.Differences(outputs[1], outputs[cores], [])));
                return outputs;
            }
            // How far a second job carries batch on a dat of 3,000 Setups (issue 30): batch alone, both places.
            foreach (var (output, root) in options.Runs("scaling") ? OutputPlaces(options) : [])
            {
                var place = new RunFolders(root, output == "disk");
                Batches(BenchReport.ScalingSize, $"{scaling.Setups}-Setup dat", scaling, output, place);
                if (output != "disk") place.Clear();
            }
            foreach (var (size, dat) in options.Runs("export") ? new[] { ("quarter", quarter), ("full", full) } : [])
            {
                foreach (var jobs in jobCounts)
                    timings.Add(Measure(log, options, "floor", size, jobs, "none", "read and decode every Setup and the GfxObjs its parts name, discard (bench process)",
                        _ => ProcessRunner.Run(BenchExecutable, ["floor", "--dat", dat.Directory, "--jobs", Text(jobs)])));
                timings.Add(Measure(log, options, "doctor", size, cores, "none", $"acshadow doctor --jobs {cores}: every check, and batch --all twice in memory",
                    _ => ProcessRunner.Run(options.Cli, ["doctor", "--dat", dat.Directory, "--jobs", Text(cores)])));
                foreach (var (output, root) in OutputPlaces(options))
                {
                    var place = new RunFolders(root, output == "disk");
                    var outputs = Batches(size, size, dat, output, place);
                    if (output == "disk")
                    {
                        // The everyday re-run into the folder the last run wrote; with the same dat every file already holds its bytes.
                        var again = place.Empty($"again-{size}", -2);
                        ProcessRunner.Run(options.Cli, ["batch", "--all", "--dat", dat.Directory, "--out", again, "--quiet"]);
                        timings.Add(Measure(log, options, "batch, again into its output", size, cores, output, $"acshadow batch --all --jobs {cores} --quiet into the folder the previous run wrote (same dat: every file already holds its bytes)",
                            _ => ProcessRunner.Run(options.Cli, ["batch", "--all", "--dat", dat.Directory, "--out", again, "--jobs", Text(cores), "--quiet"])));

                        var incrementalOut = place.Empty($"incremental-{size}", -2);
                        ProcessRunner.Run(options.Cli, ["batch", "--all", "--dat", dat.Directory, "--out", incrementalOut, "--incremental", "--quiet"]);
                        timings.Add(Measure(log, options, "batch --incremental", size, cores, output, "acshadow batch --all --incremental --quiet, nothing changed since the last run",
                            _ => ProcessRunner.Run(options.Cli, ["batch", "--all", "--dat", dat.Directory, "--out", incrementalOut, "--incremental", "--quiet"])));
                        checks.Add(new Check($"--incremental output identical to a full run ({size})", OutputComparison.Differences(incrementalOut, outputs[cores], ["incremental.json"])));
                    }
                    // Disk folders stay until the bench ends: deleting them now would slow the next disk runs (RunFolders).
                    if (output != "disk") place.Clear();
                }
            }

            // chart --all at the scale of a real dat: one timed run (it takes minutes), default spacing and
            // probe radius, every core, streamed into a folder on disk. Not in --small: CI times nothing.
            if (!options.Small && options.Runs("chart-all"))
            {
                var chartOut = Path.Combine(options.WorkDirectory, "chart");
                timings.Add(Measure(log, options with { Repetitions = 1 }, "chart --all", "full", cores, "disk",
                    $"acshadow chart --all --jobs {cores} --quiet, default spacing and probe radius (one run, no warm-up)",
                    _ => { Reset(chartOut); return ProcessRunner.Run(options.Cli, ["chart", "--all", "--dat", full.Directory, "--out", chartOut, "--jobs", Text(cores), "--quiet"]); },
                    warmUp: false));
                Reset(chartOut);
            }

            var dumpOut = Path.Combine(options.WorkDirectory, "dump");
            if (options.Runs("startup")) StartUp(log, options, timings, full, dumpOut);
            if (options.Runs("landblock")) Landblocks(log, options, timings, checks, extraRatios, full);
            if (options.Runs("cells")) Cells(log, options, timings, cores, full);
        }
        finally
        {
            foreach (var (_, root) in OutputPlaces(options))
                try { Directory.Delete(root, true); } catch (IOException) { }
        }
        return Report(log, options, machine, started, full, quarter, scaling, timings, checks, extraRatios);
    }

    /// <summary>
    /// Start-up: `--version` against `dump` of the door, as built and as `dotnet tool install` put it on the PATH. The
    /// five take turns run by run, as batch's job counts do: each is about 30 ms, and one measured after another drifted
    /// apart by more than the 1.3 target's margin (installed dump / --version 1.32 where the same binary by its own path,
    /// measured minutes earlier, gave 1.15).
    /// </summary>
    private static void StartUp(TextWriter log, HarnessOptions options, List<Timing> timings, CachedDat full, string dumpOut)
    {
        string[] dump = ["dump", "--setup", DoorSetup, "--dat", full.Directory, "--out", dumpOut];
        var workloads = new List<Workload>
        {
            new("acshadow --version", "full", 1, "none", "whole process", "version", _ => ProcessRunner.Run(options.Cli, ["--version"])),
            // Again into its own folder (the everyday case: the files are there, unchanged), and into a new one.
            new("dump --setup", "full", 1, "disk", $"acshadow dump --setup {DoorSetup} --dat (full) as a whole process, into the folder it wrote before",
                "dump", _ => ProcessRunner.Run(options.Cli, dump)),
            new("dump --setup, new folder", "full", 1, "disk", $"acshadow dump --setup {DoorSetup} --dat (full) as a whole process, into a folder that does not exist yet",
                "dump-new", _ => { Reset(dumpOut); return ProcessRunner.Run(options.Cli, dump); }),
        };
        // The same start-up as users meet it: the command `dotnet tool install` put on the PATH.
        if (options.InstalledCli is { } installed)
        {
            workloads.Add(new(BenchReport.InstalledVersion, "full", 1, "none", $"{installed} --version, whole process", "installed-version",
                _ => ProcessRunner.Run(installed, ["--version"])));
            workloads.Add(new(BenchReport.InstalledDump, "full", 1, "disk", $"{installed} dump --setup {DoorSetup} --dat (full) as a whole process, into the folder it wrote before",
                "installed-dump", _ => ProcessRunner.Run(installed, dump)));
        }
        timings.AddRange(MeasureInTurn(log, options with { Repetitions = options.StartupRepetitions }, "start-up (full, whole processes in turn)", workloads));
        Reset(dumpOut);
    }

    /// <summary>The scale dat's busy landblock charted and compiled, and the sample's landblock compiled: per-position ratios.</summary>
    private static void Landblocks(TextWriter log, HarnessOptions options, List<Timing> timings, List<Check> checks, List<Ratio> extraRatios, CachedDat full)
    {
        // The scale dat's first landblock places 60 objects: compiling it against charting it.
        var landblockOut = Path.Combine(options.WorkDirectory, "landblock");
        // --small proves both commands run; a 4 m grid keeps that to seconds (CI times nothing).
        string[] probes = options.Small ? ["--spacing", "4"] : [];
        timings.Add(Measure(log, options, "chart --landblock", "full", 1, "disk", $"acshadow chart --landblock {BusyLandblock} --quiet (60 placed objects), whole process",
            _ => { Reset(landblockOut); return ProcessRunner.Run(options.Cli, ["chart", "--landblock", BusyLandblock, "--dat", full.Directory, "--cell-dat", full.Directory, "--out", landblockOut, "--quiet", .. probes]); }));
        // What compiling saves: each timed run's scene chart, the whole landblock asked per mover position.
        var sceneCsv = Path.Combine(landblockOut, "scene-chart.csv");
        var sceneRuns = new List<SceneChartTotals>();
        timings.Add(Measure(log, options, "scene --landblock", "full", 1, "disk", $"acshadow scene --landblock {BusyLandblock} --quiet (60 placed objects), whole process",
            i =>
            {
                Reset(landblockOut);
                var outcome = ProcessRunner.Run(options.Cli, ["scene", "--landblock", BusyLandblock, "--dat", full.Directory, "--cell-dat", full.Directory, "--out", landblockOut, "--quiet", .. probes]);
                if (i >= 0) sceneRuns.Add(SceneChartTotals.Read(sceneCsv));
                return outcome;
            }));
        extraRatios.AddRange(SceneChartTotals.Ratios(BusyLandblock, sceneRuns));
        foreach (var t in sceneRuns) LogPerPosition(BusyLandblock, t);
        // The same on the built-in sample, as many runs.
        var sampleRuns = new List<SceneChartTotals>();
        for (var i = 0; i < options.Repetitions; i++)
        {
            Reset(landblockOut);
            var sample = ProcessRunner.Run(options.Cli, ["scene", "--landblock", SampleLandblock, "--out", landblockOut, "--quiet", .. probes]);
            if (!File.Exists(sceneCsv))
            {
                checks.Add(new Check($"scene --landblock {SampleLandblock} on the built-in sample runs", [sample.Stderr.Trim()]));
                break;
            }
            var t = SceneChartTotals.Read(sceneCsv);
            sampleRuns.Add(t);
            LogPerPosition($"{SampleLandblock} (sample)", t);
        }
        if (sampleRuns.Count > 0) extraRatios.AddRange(SceneChartTotals.Ratios($"{SampleLandblock} (sample)", sampleRuns));
        Reset(landblockOut);

        void LogPerPosition(string landblock, SceneChartTotals t) => log.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"scene {landblock} per mover position: all-retail {t.RetailNs:0.0} ns ({t.RetailOps:0.0} counted operations), compiled {t.CompiledNs:0.0} ns ({t.CompiledOps:0.0}), exhaustive walk {t.ExhaustiveNs:0.0} ns ({t.ExhaustiveOps:0.0}), narrow-phase floor ({t.NarrowFloorOps:0.0})"));
    }

    /// <summary>A landblock's batch with and without its indoor cells.</summary>
    private static void Cells(TextWriter log, HarnessOptions options, List<Timing> timings, int cores, CachedDat full)
    {
        // A landblock's scene with and without its interiors: the landblock with the most cells.
        var landblock = BusiestLandblock(full.Directory);
        var sceneOut = Path.Combine(options.WorkDirectory, "scene");
        foreach (var (name, extra) in new[] { ("batch --landblock, with cells", Array.Empty<string>()), ("batch --landblock --no-cells", ["--no-cells"]) })
            timings.Add(Measure(log, options, name, "full", cores, "disk", $"acshadow batch --landblock {landblock.Id} ({landblock.Cells} cells) {string.Join(' ', extra)} --quiet into a new folder",
                _ =>
                {
                    Reset(sceneOut);
                    return ProcessRunner.Run(options.Cli, ["batch", "--landblock", landblock.Id, "--dat", full.Directory, "--cell-dat", full.Directory, "--out", sceneOut, "--quiet", .. extra]);
                }));
        Reset(sceneOut);
    }

    private static BenchReport Report(TextWriter log, HarnessOptions options, MachineInfo machine, DateTime started, CachedDat full, CachedDat quarter, CachedDat scaling,
        List<Timing> timings, List<Check> checks, List<Ratio> extraRatios)
    {
        log.WriteLine("collision: reference vs brute force on GfxObjs of 200+ polygons (full dat, in-process)");
        CollisionResult collision;
        using (var dat = Workloads.Open(full.Directory)) collision = CollisionComparison.Run(dat, options.Repetitions);
        checks.Add(new Check("collision reference and brute force give the same answers",
            collision.Disagreements == 0 ? [] : [$"{collision.Disagreements} of {collision.Queries} queries disagree"]));

        var report = BenchReport.Build(options, machine, started, DateTime.UtcNow, MachineInfo.CurrentLoadAverage(), full, quarter, scaling, timings, collision, checks, extraRatios);
        report.Write(options.Output);
        report.PrintTable(log);
        log.WriteLine($"wrote {options.Output}");
        return report;
    }

    /// <summary>The scale dat's landblock with the most indoor cells (the first such id on a tie).</summary>
    private static (string Id, uint Cells) BusiestLandblock(string datDirectory)
    {
        using var cell = DatDatabase.Open(File.OpenRead(Path.Combine(datDirectory, "client_cell_1.dat")), "client_cell_1.dat");
        var (id, cells) = cell.ListIds(DatObjectKind.LandBlockInfo).Select(id => (Id: id, Cells: cell.ReadLandBlockInfo(id)!.NumCells))
            .OrderByDescending(x => x.Cells).ThenBy(x => x.Id).First();
        return (LandblockIds.Short(id), cells);
    }

    /// <summary>The work folder on disk, and the memory-backed one when there is one.</summary>
    private static IEnumerable<(string Output, string Root)> OutputPlaces(HarnessOptions options) =>
        options.MemoryWorkDirectory is { } memory ? [("disk", options.WorkDirectory), ("memory", memory)] : [("disk", options.WorkDirectory)];

    private static Timing Measure(TextWriter log, HarnessOptions options, string name, string size, int jobs, string output, string how, Func<int, ProcessRunner.Outcome> run,
        bool warmUp = true)
    {
        log.Write($"{name} ({size}, {jobs} job(s), output: {output}):{(warmUp ? " warm-up" : "")}");
        if (warmUp) run(-1);
        var seconds = new List<double>();
        var peaks = new List<double>();
        var cpu = new List<double>();
        for (var i = 0; i < options.Repetitions; i++)
        {
            var outcome = run(i);
            seconds.Add(outcome.Seconds);
            peaks.Add(outcome.PeakMiB);
            if (double.IsFinite(outcome.CpuSeconds)) cpu.Add(outcome.CpuSeconds);
            log.Write(string.Create(CultureInfo.InvariantCulture, $" {outcome.Seconds:0.000}s"));
        }
        log.WriteLine();
        return new Timing(name, size, jobs, seconds, peaks, cpu, how, output);
    }

    /// <summary>
    /// As <see cref="Measure"/> for one workload at several job counts, the counts taking turns (<see cref="MeasureInTurn"/>).
    /// </summary>
    private static IReadOnlyList<Timing> MeasureInterleaved(TextWriter log, HarnessOptions options, string name, string size, IReadOnlyList<int> jobCounts, string output,
        Func<int, string> how, Func<int, int, ProcessRunner.Outcome> run) =>
        MeasureInTurn(log, options, $"{name} ({size}, {string.Join(" and ", jobCounts)} job(s) in turn, output: {output})",
            [.. jobCounts.Select(jobs => new Workload(name, size, jobs, output, how(jobs), $"j{jobs}", i => run(jobs, i)))]);

    /// <summary>One timed workload of <see cref="MeasureInTurn"/>; <paramref name="Tag"/> names its runs in the log.</summary>
    private sealed record Workload(string Name, string Size, int Jobs, string Output, string How, string Tag, Func<int, ProcessRunner.Outcome> Run);

    /// <summary>
    /// Workloads whose times a ratio compares, taking turns: each warmed once, then repetition i of every one before
    /// repetition i + 1 of any, so a slow stretch of the machine slows them alike instead of whichever ran through it alone.
    /// </summary>
    private static IReadOnlyList<Timing> MeasureInTurn(TextWriter log, HarnessOptions options, string title, IReadOnlyList<Workload> workloads)
    {
        log.Write($"{title}: warm-up, then");
        foreach (var workload in workloads) workload.Run(-1);
        var outcomes = workloads.Select(_ => new List<ProcessRunner.Outcome>()).ToArray();
        for (var i = 0; i < options.Repetitions; i++)
            for (var k = 0; k < workloads.Count; k++)
            {
                var outcome = workloads[k].Run(i);
                outcomes[k].Add(outcome);
                log.Write(string.Create(CultureInfo.InvariantCulture, $" {workloads[k].Tag} {outcome.Seconds:0.000}s"));
            }
        log.WriteLine();
        return [.. workloads.Select((w, k) => new Timing(w.Name, w.Size, w.Jobs, [.. outcomes[k].Select(o => o.Seconds)], [.. outcomes[k].Select(o => o.PeakMiB)],
            [.. outcomes[k].Select(o => o.CpuSeconds).Where(double.IsFinite)], w.How, w.Output))];
    }

    /// <summary>The bench's own entry assembly, run again as a child process for the floor.</summary>
    private static string BenchExecutable => typeof(BenchHarness).Assembly.Location;

    /// <summary>
    /// Empties a workload's folder and flushes the file systems, so every timed run starts from the same
    /// state instead of paying for the previous run's write-back and deletions.
    /// </summary>
    internal static void Reset(string dir)
    {
        if (Directory.Exists(dir)) Directory.Delete(dir, true);
        Sync();
    }

    internal static void Sync()
    {
        if (OperatingSystem.IsLinux() || OperatingSystem.IsMacOS()) ProcessRunner.Run("sync", []);
    }

    private static string Text(int n) => n.ToString(CultureInfo.InvariantCulture);
}

/// <summary>A correctness check the harness makes on the way (empty problems: it held).</summary>
public sealed record Check(string Name, IReadOnlyList<string> Problems)
{
    public bool Passed => Problems.Count == 0;
}
