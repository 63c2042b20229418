using System.Diagnostics;

namespace AcShadow.Fuzz;

/// <summary>
/// How a campaign runs: which cases (seed, first index, count), each case's limits, and which cases are
/// deep (also run chart and verify): those whose index is a multiple of <see cref="DeepEvery"/>.
/// </summary>
public sealed record CampaignOptions(long Seed, int Cases, int Start = 0, double TimeLimitSeconds = 10, long MemoryLimitBytes = 128L << 20, int DeepEvery = 1)
{
    public TimeSpan TimeLimit => TimeSpan.FromSeconds(TimeLimitSeconds);
}

/// <summary>A failing case: its index, its input (for minimising and saving) and what went wrong.</summary>
public sealed record FoundFailure(int CaseIndex, FuzzInput Input, CaseFailure Failure);

/// <summary>
/// What a campaign found: failures (the first <see cref="FuzzCampaign.ExamplesPerSignature"/> cases of each
/// signature, and how many cases showed it), speed and the slowest case.
/// </summary>
public sealed record CampaignResult(
    int Cases,
    TimeSpan Elapsed,
    IReadOnlyList<FoundFailure> Failures,
    IReadOnlyDictionary<string, int> FailureCounts,
    int SlowestCase,
    string SlowestDescription,
    TimeSpan SlowestTime,
    IReadOnlyDictionary<int, int> ExitCodeCounts)
{
    public double CasesPerSecond => Cases / Math.Max(Elapsed.TotalSeconds, 1e-9);
    public int FailedCases => FailureCounts.Values.Sum();

    /// <summary>Cases that also ran chart and verify.</summary>
    public int DeepCases { get; init; }

    /// <summary>Time spent in each command over all cases.</summary>
    public IReadOnlyDictionary<string, TimeSpan> CommandTimes { get; init; } = new Dictionary<string, TimeSpan>();
}

/// <summary>
/// Runs cases one after another (each already runs two to four commands; the machine's cores are shared)
/// from a seed, so the same options always run the same cases.
/// </summary>
public static class FuzzCampaign
{
    /// <summary>Cases kept per kind of failure: minimising a few and saving the smallest gives a smaller reproducer.</summary>
    public const int ExamplesPerSignature = 3;

    /// <param name="starting">Called with each case's index before it runs (a crash of the whole process can then be pinned on it).</param>
    public static CampaignResult Run(IReadOnlyList<FuzzBase> bases, CampaignOptions options, string scratch,
        Action<int, CaseOutcome>? progress = null, Action<int>? starting = null)
    {
        var mutator = new DatMutator(bases);
        var runner = new CaseRunner(scratch, options.TimeLimit, options.MemoryLimitBytes);
        var failures = new List<FoundFailure>();
        var counts = new SortedDictionary<string, int>(StringComparer.Ordinal);
        var exits = new SortedDictionary<int, int>();
        var slowest = (Index: -1, Description: "", Time: TimeSpan.Zero);
        var times = new SortedDictionary<string, TimeSpan>(StringComparer.Ordinal);
        var deepCases = 0;
        var clock = Stopwatch.StartNew();
        for (var i = options.Start; i < options.Start + options.Cases; i++)
        {
            starting?.Invoke(i);
            var input = mutator.Mutate(options.Seed, i);
            var deep = i % Math.Max(1, options.DeepEvery) == 0;
            if (deep) deepCases++;
            var outcome = runner.Run(input, $"case-{i}", deep);
            foreach (var code in outcome.ExitCodes) exits[code] = exits.GetValueOrDefault(code) + 1;
            foreach (var (command, time) in outcome.CommandTimes) times[command] = times.GetValueOrDefault(command) + time;
            if (outcome.Elapsed > slowest.Time) slowest = (i, input.Description, outcome.Elapsed);
            if (outcome.Failure is { } failure)
            {
                counts.TryGetValue(failure.Signature, out var seen);
                if (seen < ExamplesPerSignature) failures.Add(new FoundFailure(i, input, failure));
                counts[failure.Signature] = seen + 1;
            }
            progress?.Invoke(i, outcome);
        }
        return new CampaignResult(options.Cases, clock.Elapsed, failures, counts, slowest.Index, slowest.Description, slowest.Time, exits)
        {
            DeepCases = deepCases,
            CommandTimes = times,
        };
    }
}
