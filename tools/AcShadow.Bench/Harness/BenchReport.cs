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
    IReadOnlyList<Timing> Timings,
    CollisionResult Collision,
    IReadOnlyList<Check> Checks,
    IReadOnlyList<Ratio> Ratios)
{
    public const string Format = "acshadow.bench/1";
    public const double MemoryLimitMiB = 400;

    public static BenchReport Build(HarnessOptions options, MachineInfo machine, DateTime started, DateTime finished, CachedDat full, CachedDat quarter,
        IReadOnlyList<Timing> timings, CollisionResult collision, IReadOnlyList<Check> checks, IReadOnlyList<Ratio>? measured = null)
    {
        var cores = timings.Where(t => t.Name == "batch").Max(t => t.Jobs);
        Timing Get(string name, string size, int jobs, string output = "disk") =>
            timings.Single(t => t.Name == name && t.Size == size && t.Jobs == jobs && t.Output == output);
        var ratios = new List<Ratio>();
        // The write workloads' targets on each place they ran: the disk shows what a user waits for, memory
        // (tmpfs) what the tool itself costs once file creation is cheap.
        foreach (var output in timings.Where(t => t.Name == "batch").Select(t => t.Output).Distinct())
        {
            var where = output == "disk" ? "" : $" ({output})";
            var b1 = Get("batch", "full", 1, output);
            var bN = Get("batch", "full", cores, output);
            var naive = Get("naive", "full", 1, output);
            ratios.Add(new($"batch / floor, 1 job{where}", b1.Median / Get("floor", "full", 1, "none").Median, "<=", 1.25, $"batch --all --jobs 1 over the floor at 1 job, output on {output}"));
            ratios.Add(new($"batch / floor, {cores} jobs{where}", bN.Median / Get("floor", "full", cores, "none").Median, "<=", 1.25, $"batch --all --jobs {cores} over the floor at {cores} jobs, output on {output}"));
            ratios.Add(new($"naive / batch, 1 job{where}", naive.Median / b1.Median, ">=", 5, $"how many times faster batch --jobs 1 is than the naive exporter (1 job), both writing to {output}"));
            ratios.Add(new($"naive / batch, {cores} jobs{where}", naive.Median / bN.Median, ">=", 5, $"the same, batch at {cores} jobs"));
            ratios.Add(new($"batch 1 job / {cores} jobs{where}", b1.Median / bN.Median, ">=", cores > 1 ? 1.7 : 1, $"speed-up from all cores, output on {output}"));
        }
        var batch1 = Get("batch", "full", 1);
        var batchN = Get("batch", "full", cores);
        ratios.AddRange(
        [
            new("incremental / full run", Get("batch --incremental", "full", cores).Median / batchN.Median, "<=", 0.5, "--incremental with nothing changed over a full run"),
            new("dump / --version", Get("dump --setup", "full", 1).Median / Get("acshadow --version", "full", 1, "none").Median, "<=", 1.3, "dump --setup as a whole process over acshadow --version, into the folder it wrote before"),
            new("dump into a new folder / --version", Get("dump --setup, new folder", "full", 1).Median / Get("acshadow --version", "full", 1, "none").Median, "<=", 1.3, "the same, every file created"),
            new($"peak MiB, batch {cores} jobs (full)", batchN.PeakMedianMiB, "<=", MemoryLimitMiB, "peak resident memory of batch --all"),
            new("peak MiB, batch 1 job (full)", batch1.PeakMedianMiB, "<=", MemoryLimitMiB, "peak resident memory of batch --all --jobs 1"),
            new($"peak full / quarter, batch {cores} jobs", batchN.PeakMedianMiB / Get("batch", "quarter", cores).PeakMedianMiB, "<=", 1.3, "how peak memory grows with the dat"),
            new($"doctor / batch, {cores} jobs", Get("doctor", "full", cores, "none").Median / batchN.Median, "<=", 2, "acshadow doctor over batch --all, both at all cores, batch writing to disk"),
            new($"peak full / quarter, doctor {cores} jobs", Get("doctor", "full", cores, "none").PeakMedianMiB / Get("doctor", "quarter", cores, "none").PeakMedianMiB, "<=", 1.3, "how the doctor's peak memory grows with the dat"),
            new("scene / chart --landblock", Get("scene --landblock", "full", 1).Median / Get("chart --landblock", "full", 1).Median, "<=", 2,
                $"compiling the scale dat's {AcShadow.Forge.Scale.ScaleSpecGenerator.BusyLandblockObjects}-object landblock over charting it, whole processes"),
            new("brute force / reference", Timing.MedianOf(collision.BruteForceNanoseconds) / Timing.MedianOf(collision.ReferenceNanoseconds), ">=", 5,
                $"per-query speed-up of the collision reference on GfxObjs of {CollisionComparison.MinPolygons}+ polygons"),
        ]);
        // Not measured by --small (CI times nothing).
        if (timings.FirstOrDefault(t => t.Name == "chart --all") is { } chartAll)
            ratios.Add(new($"chart --all, {cores} jobs (full), minutes", chartAll.Median / 60, "<=", 30,
                $"the whole scale dat charted at default spacing and probe radius, {chartAll.PeakMedianMiB:0} MiB peak"));
        ratios.AddRange(measured ?? []);
        return new BenchReport(options, machine, started, finished, full, quarter, timings, collision, checks, ratios);
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
            w.WriteNumber("loadAverageAtEnd", MachineInfo.CurrentLoadAverage());
            w.WriteEndObject();
            w.WriteStartObject("parameters");
            w.WriteBoolean("small", Options.Small);
            w.WriteNumber("repetitions", Options.Repetitions);
            w.WriteNumber("startupRepetitions", Options.StartupRepetitions);
            w.WriteString("cli", Options.Cli);
            w.WriteString("work", Options.WorkDirectory);
            if (Options.MemoryWorkDirectory is { } memory) w.WriteString("memoryWork", memory);
            w.WriteEndObject();
            w.WriteStartObject("dats");
            foreach (var (name, dat) in new[] { ("full", Full), ("quarter", Quarter) })
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

    /// <summary>The table docs/performance.md shows (Markdown, so it pastes as is).</summary>
    public void PrintTable(TextWriter o)
    {
        o.WriteLine(Invariant($"Scale dat: {Full.Setups} Setups, {Full.GfxObjs} GfxObjs, {Full.PortalBytes / 1048576.0:0} MiB (forged in {Full.GenerationSeconds:0.0} s); quarter: {Quarter.Setups} Setups, {Quarter.GfxObjs} GfxObjs, {Quarter.PortalBytes / 1048576.0:0} MiB."));
        o.WriteLine(Invariant($"Machine: {Machine.Cores} cores, {Machine.Cpu}, {Machine.RamGiB:0} GiB RAM, {Machine.Os}, {Machine.Dotnet}; load average {Machine.LoadAverage:0.0} at start. Each figure: median of {Options.Repetitions} run(s) after a warm-up."));
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
            o.WriteLine(Invariant($"| {r.Name} | {r.Value:0.00} | {r.Comparison.Replace("<=", "≤").Replace(">=", "≥")} {r.Target} | {(r.Met ? "yes" : "**no**")} |"));
        foreach (var c in Checks)
            o.WriteLine($"| {c.Name} | {(c.Passed ? "yes" : string.Join("; ", c.Problems))} | yes | {(c.Passed ? "yes" : "**no**")} |");
        o.WriteLine(Invariant($"Collision: {Collision.GfxObjs} GfxObjs of {Collision.MinPolygons}-{Collision.MaxPolygons} physics polygons (median {Collision.MedianPolygons}), {Collision.Queries} probes, {Collision.Disagreements} disagreements."));
    }

    private static double Round(double v) => double.IsFinite(v) ? Math.Round(v, 4) : 0;

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
