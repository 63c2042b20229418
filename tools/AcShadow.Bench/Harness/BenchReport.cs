using System.Globalization;
using System.Text;
using System.Text.Json;

namespace AcShadow.Bench.Harness;

/// <summary>One ratio the issue sets a target for, as measured: met when it is on the right side of the target.</summary>
public sealed record Ratio(string Name, double Value, string Comparison, double Target, string Meaning)
{
    public bool Met => Comparison == "<=" ? Value <= Target : Value >= Target;
}

/// <summary>Everything one harness run measured: bench.json and the printed table.</summary>
public sealed record BenchReport(
    HarnessOptions Options,
    MachineInfo Machine,
    DateTime Started,
    DateTime Finished,
    CachedDat Full,
    CachedDat Quarter,
    CachedDat Scaling,
    double LoadAverageAtEnd,
    IReadOnlyList<double> CoreLoopMsAtEnd,
    IReadOnlyList<Timing> Timings,
    CollisionResult Collision,
    IReadOnlyList<Check> Checks,
    IReadOnlyList<Ratio> Ratios)
{
    public const string Format = "acshadow.bench/1";
    public const double MemoryLimitMiB = 400;

    /// <summary>Issue 30: one landblock's scene compile fits in this much resident memory.</summary>
    public const double SceneMemoryLimitMiB = 300;

    /// <summary>Issue 30: the speed-up a second job gives on the scaling dat (<see cref="HarnessOptions.ScalingSetups"/> Setups).</summary>
    public const double ScalingTarget = 1.6;

    /// <summary>The timings' size label for the scaling dat, and the names of the installed tool's start-up rows.</summary>
    public const string ScalingSize = "scaling";
    public const string InstalledVersion = "installed acshadow --version";
    public const string InstalledDump = "installed dump --setup";

    public static BenchReport Build(HarnessOptions options, MachineInfo machine, DateTime started, DateTime finished, double loadAtEnd,
        CachedDat full, CachedDat quarter, CachedDat scaling, IReadOnlyList<Timing> timings, CollisionResult collision, IReadOnlyList<Check> checks,
        IReadOnlyList<Ratio>? measured = null)
    {
        var cores = timings.Where(t => t.Name == "batch").Select(t => t.Jobs).DefaultIfEmpty(Environment.ProcessorCount).Max();
        Timing Get(string name, string size, int jobs, string output = "disk") =>
            timings.SingleOrDefault(t => t.Name == name && t.Size == size && t.Jobs == jobs && t.Output == output) ?? throw new SkippedWorkload();
        var ratios = new List<Ratio>();
        // A ratio whose workloads this run did not measure (--only) is left out, not reported as zero.
        void Add(Func<Ratio> ratio)
        {
            try { ratios.Add(ratio()); }
            catch (SkippedWorkload) { }
        }
        // What all cores buy on each place the batches ran: the disk shows what a user waits for, memory (tmpfs)
        // what the tool itself costs once file creation is cheap. Batch against the floor and against a naive
        // exporter are retired (docs/performance.md: neither could be met without writing less than consumers read).
        foreach (var output in timings.Where(t => t.Name == "batch").Select(t => t.Output).Distinct())
        {
            var where = output == "disk" ? "" : $" ({output})";
            Add(() => new($"batch 1 job / {cores} jobs{where}", Get("batch", "full", 1, output).Median / Get("batch", "full", cores, output).Median, ">=", cores > 1 ? 1.7 : 1,
                $"speed-up from all cores on the scale dat, output on {output}"));
            Add(() => new($"batch 1 job / {cores} jobs, {scaling.Setups}-Setup dat{where}",
                Get("batch", ScalingSize, 1, output).Median / Get("batch", ScalingSize, cores, output).Median, ">=", cores > 1 ? ScalingTarget : 1,
                $"speed-up from all cores on the {scaling.Setups}-Setup / {scaling.GfxObjs}-GfxObj dat (seed {scaling.Seed}), output on {output}"));
        }
        Timing Batch1() => Get("batch", "full", 1);
        Timing BatchN() => Get("batch", "full", cores);
        foreach (var ratio in new Func<Ratio>[]
        {
            () => new("incremental / full run", Get("batch --incremental", "full", cores).Median / BatchN().Median, "<=", 0.5, "--incremental with nothing changed over a full run"),
            () => new("dump / --version", Get("dump --setup", "full", 1).Median / Get("acshadow --version", "full", 1, "none").Median, "<=", 1.3, "dump --setup as a whole process over acshadow --version, into the folder it wrote before"),
            () => new("dump into a new folder / --version", Get("dump --setup, new folder", "full", 1).Median / Get("acshadow --version", "full", 1, "none").Median, "<=", 1.3, "the same, every file created"),
            () => new("peak MiB, scene --landblock (full)", Get("scene --landblock", "full", 1).PeakMedianMiB, "<=", SceneMemoryLimitMiB,
                $"peak resident memory of compiling the scale dat's {AcShadow.Forge.Scale.ScaleSpecGenerator.BusyLandblockObjects}-object landblock"),
            () => new($"peak MiB, batch {cores} jobs (full)", BatchN().PeakMedianMiB, "<=", MemoryLimitMiB, "peak resident memory of batch --all"),
            () => new("peak MiB, batch 1 job (full)", Batch1().PeakMedianMiB, "<=", MemoryLimitMiB, "peak resident memory of batch --all --jobs 1"),
            () => new($"peak full / quarter, batch {cores} jobs", BatchN().PeakMedianMiB / Get("batch", "quarter", cores).PeakMedianMiB, "<=", 1.3, "how peak memory grows with the dat"),
            () => new($"doctor / batch, {cores} jobs", Get("doctor", "full", cores, "none").Median / BatchN().Median, "<=", 2, "acshadow doctor over batch --all, both at all cores, batch writing to disk"),
            () => new($"peak full / quarter, doctor {cores} jobs", Get("doctor", "full", cores, "none").PeakMedianMiB / Get("doctor", "quarter", cores, "none").PeakMedianMiB, "<=", 1.3, "how the doctor's peak memory grows with the dat"),
            () => new("scene / chart --landblock", Get("scene --landblock", "full", 1).Median / Get("chart --landblock", "full", 1).Median, "<=", 2,
                $"compiling the scale dat's {AcShadow.Forge.Scale.ScaleSpecGenerator.BusyLandblockObjects}-object landblock over charting it, whole processes"),
            () => new("brute force / reference", Timing.MedianOf(collision.BruteForceNanoseconds) / Timing.MedianOf(collision.ReferenceNanoseconds), ">=", 5,
                $"per-query speed-up of the collision reference on GfxObjs of {CollisionComparison.MinPolygons}+ polygons"),
        })
            Add(ratio);
        // Not measured by --small (CI times nothing).
        if (timings.FirstOrDefault(t => t.Name == "chart --all") is { } chartAll)
            Add(() => new($"chart --all, {cores} jobs (full), minutes", chartAll.Median / 60, "<=", 30,
                $"the whole scale dat charted at default spacing and probe radius, {chartAll.PeakMedianMiB:0} MiB peak"));
        // What `dotnet tool install` put on the PATH (scripts/bench.sh packs and installs it), when measured.
        if (timings.FirstOrDefault(t => t.Name == InstalledVersion) is { } installedVersion)
            Add(() => new("dump / --version, installed tool", Get(InstalledDump, "full", 1).Median / installedVersion.Median, "<=", 1.3,
                $"dump --setup over --version, both run as the command `dotnet tool install` put on the PATH ({options.InstalledCli})"));
        ratios.AddRange(measured ?? []);
        return new BenchReport(options, machine, started, finished, full, quarter, scaling, loadAtEnd, CoreSpeed.Measure(), timings, collision, checks, ratios);
    }

    public void Write(string path)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("format", Format);
            w.WriteString("started", Started.ToString("O", CultureInfo.InvariantCulture));
            w.WriteNumber("wallSeconds", Math.Round((Finished - Started).TotalSeconds, 1));
            w.WriteStartObject("machine");
            w.WriteNumber("cores", Machine.Cores);
            w.WriteString("cpu", Machine.Cpu);
            w.WriteNumber("ramGiB", Math.Round(Machine.RamGiB, 1));
            w.WriteString("os", Machine.Os);
            w.WriteString("dotnet", Machine.Dotnet);
            w.WriteNumber("loadAverageAtStart", Machine.LoadAverage);
            w.WriteNumber("loadAverageAtEnd", LoadAverageAtEnd);
            WriteNumbers(w, "coreLoopMsAtStart", Machine.CoreLoopMs);
            WriteNumbers(w, "coreLoopMsAtEnd", CoreLoopMsAtEnd);
            w.WriteEndObject();
            w.WriteStartObject("parameters");
            w.WriteBoolean("small", Options.Small);
            w.WriteNumber("repetitions", Options.Repetitions);
            w.WriteNumber("startupRepetitions", Options.StartupRepetitions);
            w.WriteString("cli", Options.Cli);
            w.WriteString("work", Options.WorkDirectory);
            if (Options.MemoryWorkDirectory is { } memory) w.WriteString("memoryWork", memory);
            if (Options.InstalledCli is { } installed) w.WriteString("installedCli", installed);
            w.WriteString("only", string.Join(",", HarnessOptions.Groups.Where(Options.Runs)));
            w.WriteEndObject();
            w.WriteStartObject("dats");
            foreach (var (name, dat) in new[] { ("full", Full), ("quarter", Quarter), (ScalingSize, Scaling) })
            {
                w.WriteStartObject(name);
                w.WriteNumber("setups", dat.Setups);
                w.WriteNumber("gfxObjs", dat.GfxObjs);
                w.WriteNumber("seed", dat.Seed);
                w.WriteNumber("portalBytes", dat.PortalBytes);
                w.WriteNumber("generationSeconds", dat.GenerationSeconds);
                w.WriteBoolean("cached", dat.WasCached);
                w.WriteString("path", dat.Directory);
                w.WriteEndObject();
            }
            w.WriteEndObject();
            w.WriteStartArray("timings");
            foreach (var t in Timings)
            {
                w.WriteStartObject();
                w.WriteString("name", t.Name);
                w.WriteString("size", t.Size);
                w.WriteNumber("jobs", t.Jobs);
                w.WriteString("output", t.Output);
                w.WriteString("how", t.How);
                w.WriteNumber("medianSeconds", Round(t.Median));
                w.WriteNumber("minSeconds", Round(t.Min));
                w.WriteNumber("maxSeconds", Round(t.Max));
                w.WriteNumber("spread", Round(t.Spread));
                w.WriteNumber("peakMiB", Math.Round(t.PeakMedianMiB, 1));
                w.WriteNumber("cpuSeconds", Round(t.CpuMedian));
                w.WriteStartArray("seconds");
                foreach (var s in t.Seconds) w.WriteNumberValue(Round(s));
                w.WriteEndArray();
                w.WriteStartArray("peaksMiB");
                foreach (var p in t.PeakMiB) w.WriteNumberValue(Math.Round(p, 1));
                w.WriteEndArray();
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartObject("collision");
            w.WriteNumber("gfxObjs", Collision.GfxObjs);
            w.WriteNumber("minPolygons", Collision.MinPolygons);
            w.WriteNumber("medianPolygons", Collision.MedianPolygons);
            w.WriteNumber("maxPolygons", Collision.MaxPolygons);
            w.WriteNumber("queries", Collision.Queries);
            w.WriteNumber("disagreements", Collision.Disagreements);
            w.WriteNumber("referenceNanosecondsPerQuery", Round(Timing.MedianOf(Collision.ReferenceNanoseconds)));
            w.WriteNumber("bruteForceNanosecondsPerQuery", Round(Timing.MedianOf(Collision.BruteForceNanoseconds)));
            w.WriteEndObject();
            w.WriteStartArray("ratios");
            foreach (var r in Ratios)
            {
                w.WriteStartObject();
                w.WriteString("name", r.Name);
                w.WriteNumber("value", Round(r.Value));
                w.WriteString("target", $"{r.Comparison} {r.Target.ToString(CultureInfo.InvariantCulture)}");
                w.WriteBoolean("met", r.Met);
                w.WriteString("meaning", r.Meaning);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("checks");
            foreach (var c in Checks)
            {
                w.WriteStartObject();
                w.WriteString("name", c.Name);
                w.WriteBoolean("passed", c.Passed);
                w.WriteStartArray("problems");
                foreach (var p in c.Problems) w.WriteStringValue(p);
                w.WriteEndArray();
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteEndObject();
        }
        var directory = Path.GetDirectoryName(Path.GetFullPath(path));
        if (directory is not null) Directory.CreateDirectory(directory);
        File.WriteAllBytes(path, [.. stream.ToArray(), (byte)'\n']);
    }

    private static void WriteNumbers(Utf8JsonWriter w, string name, IReadOnlyList<double> values)
    {
        w.WriteStartArray(name);
        foreach (var v in values) w.WriteNumberValue(v);
        w.WriteEndArray();
    }

    /// <summary>The table docs/performance.md shows (Markdown, so it pastes as is).</summary>
    public void PrintTable(TextWriter o)
    {
        o.WriteLine(Invariant($"Scale dat: {Full.Setups} Setups, {Full.GfxObjs} GfxObjs, {Full.PortalBytes / 1048576.0:0} MiB (forged in {Full.GenerationSeconds:0.0} s); quarter: {Quarter.Setups} Setups, {Quarter.GfxObjs} GfxObjs, {Quarter.PortalBytes / 1048576.0:0} MiB; scaling: {Scaling.Setups} Setups, {Scaling.GfxObjs} GfxObjs, seed {Scaling.Seed}, {Scaling.PortalBytes / 1048576.0:0} MiB."));
        o.WriteLine(Invariant($"Conditions: {Machine.Cores} cores, {Machine.Cpu}, {Machine.RamGiB:0} GiB RAM, {Machine.Os}, {Machine.Dotnet}; load average {Machine.LoadAverage:0.00} at the start and {LoadAverageAtEnd:0.00} at the end ({Started:yyyy-MM-dd HH:mm}-{Finished:HH:mm} UTC). Each figure: median of {Options.Repetitions} run(s) after a warm-up. Workloads: {string.Join(", ", HarnessOptions.Groups.Where(Options.Runs))}."));
        if (Machine.CoreLoopMs.Count > 0)
            o.WriteLine(Invariant($"Core speeds (one fixed loop pinned to each core, ms): {string.Join(" / ", Machine.CoreLoopMs)} at the start, {string.Join(" / ", CoreLoopMsAtEnd)} at the end; a core slower than its neighbour is shared with another tenant, and slows what runs on it."));
        o.WriteLine();
        o.WriteLine("| What | Dat | Jobs | Output | Median s | Min s | Max s | CPU s | Peak MiB |");
        o.WriteLine("|---|---|---|---|---|---|---|---|---|");
        foreach (var t in Timings)
            o.WriteLine(Invariant($"| {t.Name} | {t.Size} | {t.Jobs} | {t.Output} | {t.Median:0.000} | {t.Min:0.000} | {t.Max:0.000} | {t.CpuMedian:0.00} | {t.PeakMedianMiB:0} |"));
        o.WriteLine(Invariant($"| collision reference, per query | full | 1 | none | {Timing.MedianOf(Collision.ReferenceNanoseconds):0} ns | | | | |"));
        o.WriteLine(Invariant($"| collision brute force, per query | full | 1 | none | {Timing.MedianOf(Collision.BruteForceNanoseconds):0} ns | | | | |"));
        o.WriteLine();
        o.WriteLine("| Target | Measured | Goal | Met |");
        o.WriteLine("|---|---|---|---|");
        foreach (var r in Ratios)
            // Three places: a ratio of 0.503 against a goal of 0.5 read "0.50 | ≤ 0.5 | no" with two.
            o.WriteLine(Invariant($"| {r.Name} | {r.Value:0.000} | {r.Comparison.Replace("<=", "≤").Replace(">=", "≥")} {r.Target:0.###} | {(r.Met ? "yes" : "**no**")} |"));
        foreach (var c in Checks)
            o.WriteLine($"| {c.Name} | {(c.Passed ? "yes" : string.Join("; ", c.Problems))} | yes | {(c.Passed ? "yes" : "**no**")} |");
        o.WriteLine(Invariant($"Collision: {Collision.GfxObjs} GfxObjs of {Collision.MinPolygons}-{Collision.MaxPolygons} physics polygons (median {Collision.MedianPolygons}), {Collision.Queries} probes, {Collision.Disagreements} disagreements."));
    }

    private static double Round(double v) => double.IsFinite(v) ? Math.Round(v, 4) : 0;

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}

/// <summary>A workload this run skipped (<c>--only</c>): the ratios built on it are left out.</summary>
internal sealed class SkippedWorkload : Exception;
