using AcShadow.Forge.Scale;

namespace AcShadow.Bench.Harness;

/// <summary>
/// What one harness run measures: the scale dat's parameters (its quarter-size twin is derived), how many
/// timed repetitions after one warm-up, where the CLI and the caches are, and where bench.json goes.
/// </summary>
public sealed record HarnessOptions(
    int Setups,
    int GfxObjs,
    int Seed,
    int Repetitions,
    int StartupRepetitions,
    string Cli,
    string CacheDirectory,
    string WorkDirectory,
    string? MemoryWorkDirectory,
    string Output,
    bool Small)
{
    public const string Usage =
        "usage: AcShadow.Bench harness --cli PATH [--installed PATH] [--small] [--setups N] [--gfxobjs M] [--seed S] [--reps R] [--cache DIR] [--work DIR] [--memory-work DIR|none] [--only GROUP,...] [--out bench.json]";

    /// <summary>
    /// The command `dotnet tool install` put on the PATH (scripts/bench.sh packs the tool and installs it into a
    /// folder of its own): its start-up is timed as users meet it. Null: not measured.
    /// </summary>
    public string? InstalledCli { get; init; }

    /// <summary>The workload groups a run can be limited to with <c>--only</c>; every group runs by default.</summary>
    public static readonly IReadOnlyList<string> Groups = ["export", "scaling", "chart-all", "startup", "landblock", "cells"];

    /// <summary>
    /// The groups this run measures (<c>--only export,scaling</c>): a run of a few targets on a quiet machine takes
    /// minutes where the whole run takes most of an hour. Ratios whose workloads were skipped are left out.
    /// </summary>
    public IReadOnlySet<string> Only { get; init; } = Groups.ToHashSet(StringComparer.Ordinal);

    /// <summary>Does this run measure the group?</summary>
    public bool Runs(string group) => Only.Contains(group);

    /// <summary>The dat `batch --all` scales from one job to all cores on (issue 30): 3,000 Setups, 15,000 GfxObjs, seed 7.</summary>
    public const int ScalingSetups = 3000, ScalingGfxObjs = 15000, ScalingSeed = 7;

    /// <summary>The scaling dat --small forges instead: a few Setups, proving the rows run (CI times nothing).</summary>
    public const int SmallScalingSetups = 40;

    /// <summary>
    /// Where the write workloads run a second time, on a memory-backed file system, so the table shows the
    /// tool's own cost beside the disk's: /dev/shm when the machine has it.
    /// </summary>
    private static string? DefaultMemoryWork() =>
        Directory.Exists("/dev/shm") ? Path.Combine("/dev/shm", $"acshadow-bench-{Environment.ProcessId}") : null;

    /// <summary>CI size: a few hundred Setups, one repetition; proves the harness works, not the timings.</summary>
    public const int SmallSetups = 200;

    public static HarnessOptions Parse(IReadOnlyList<string> args)
    {
        var a = new BenchArgs(args, Usage);
        var small = a.Has("--small");
        string? Value(string name) => a.Value(name);
        int Int(string name, int fallback) => a.PositiveInt(name, fallback);

        var setups = Int("--setups", small ? SmallSetups : ScaleSpecGenerator.DefaultSetups);
        var cli = a.Required("--cli", "the acshadow executable (or acshadow.dll) to measure");
        var cache = Value("--cache") ?? Path.Combine(Path.GetTempPath(), "acshadow-bench-cache");
        return new HarnessOptions(
            setups,
            Int("--gfxobjs", ScaleSpecGenerator.GfxObjsFor(setups)),
            Int("--seed", ScaleSpecGenerator.DefaultSeed),
            Int("--reps", small ? 1 : 3),
            Int("--startup-reps", small ? 2 : 40),
            Path.GetFullPath(cli),
            Path.GetFullPath(cache),
            Path.GetFullPath(Value("--work") ?? Path.Combine(Path.GetTempPath(), $"acshadow-bench-{Environment.ProcessId}")),
            Value("--memory-work") is { } memory ? (memory == "none" ? null : Path.GetFullPath(memory)) : DefaultMemoryWork(),
            Path.GetFullPath(Value("--out") ?? "bench.json"),
            small)
        {
            InstalledCli = Value("--installed") is { } installed ? Path.GetFullPath(installed) : null,
            Only = Value("--only") is { } only ? ParseGroups(only) : Groups.ToHashSet(StringComparer.Ordinal),
        };
    }

    private static HashSet<string> ParseGroups(string text)
    {
        var groups = text.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).ToHashSet(StringComparer.Ordinal);
        if (groups.Count == 0 || groups.Any(g => !Groups.Contains(g)))
            throw new ArgumentException($"--only takes workload groups separated by commas ({string.Join(", ", Groups)}), not \"{text}\"");
        return groups;
    }
}
