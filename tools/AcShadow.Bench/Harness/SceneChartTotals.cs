using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>
/// The three landblock rows of a scene-chart.csv `acshadow scene` wrote: the whole scene's median time and
/// counted operations per mover position, every object as retail and as compiled (both through the
/// land-cell partition), and every object as retail asked of every object and cell (the exhaustive walk); and the
/// narrow-phase floor, counted only: what no broad phase in front of all-retail can save.
/// </summary>
public sealed record SceneChartTotals(double RetailNs, double CompiledNs, double RetailOps, double CompiledOps, double ExhaustiveNs, double ExhaustiveOps,
    double NarrowFloorOps)
{
    /// <summary>Compiled over all-retail per position: compiling must at least halve the time.</summary>
    public const double CompiledTarget = 0.5;

    /// <summary>All-retail through the partition over the exhaustive walk: at least three times faster.</summary>
    public const double PartitionTarget = 1.0 / 3.0;

    public static SceneChartTotals Read(string csvPath)
    {
        var lines = File.ReadAllLines(csvPath);
        var header = lines[0].Split(',');
        int Column(string name) => Array.IndexOf(header, name) is var i and >= 0 ? i : throw new FormatException($"{csvPath}: no {name} column");
        string[] Row(string model) => lines.Skip(1).Select(l => l.Split(',')).FirstOrDefault(r => r[0] == "landblock" && r[Column("model")] == model)
            ?? throw new FormatException($"{csvPath}: no landblock row for {model}");
        double Number(string[] row, string column) => double.Parse(row[Column(column)], NumberStyles.Float, CultureInfo.InvariantCulture);
        var retail = Row("all-retail");
        var compiled = Row("compiled");
        var exhaustive = Row("all-retail-exhaustive");
        var floor = Row("all-retail-narrow-floor");
        return new SceneChartTotals(Number(retail, "median_ns"), Number(compiled, "median_ns"), Number(retail, "ops"), Number(compiled, "ops"),
            Number(exhaustive, "median_ns"), Number(exhaustive, "ops"), Number(floor, "ops"));
    }

    /// <summary>
    /// Compiled over all-retail, per position (below 1: compiling saves), and all-retail through the land-cell
    /// partition over the exhaustive walk: time and counted operations, each measured interleaved within one run of
    /// the scene command. Over several runs, each timed ratio is the median of the runs' own ratios, and its meaning
    /// lists every run's: one run that a busy stretch of the machine slowed does not decide it.
    /// </summary>
    public static IReadOnlyList<Ratio> Ratios(string landblock, IReadOnlyList<SceneChartTotals> runs)
    {
        if (runs.Count == 0) throw new ArgumentException("no scene run to read ratios from", nameof(runs));
        var last = runs[^1];
        // A timed ratio is the runs' median, each run's listed; a counted one is the same in every run, so the last run's.
        Ratio Timed(string name, Func<SceneChartTotals, double> ratio, double target, string meaning) =>
            new(name, Median(runs.Select(ratio)), "<=", target, runs.Count == 1 ? meaning
                : meaning + Invariant($"; the median of {runs.Count} runs' ratios (runs: ") + string.Join(", ", runs.Select(r => Invariant($"{ratio(r):0.000}"))) + ")");
        return
        [
            Timed($"scene {landblock}: compiled / all-retail, ns per position", r => r.CompiledNs / r.RetailNs, CompiledTarget,
                Invariant($"median time to ask the whole scene about one mover position, compiled ({last.CompiledNs:0.0} ns in the last run) over every object as retail ({last.RetailNs:0.0} ns), both through the land-cell partition, measured by the scene command interleaved")),
            new($"scene {landblock}: compiled / all-retail, counted operations", last.CompiledOps / last.RetailOps, "<=", CompiledTarget,
                Invariant($"counted distance evaluations per mover position, compiled ({last.CompiledOps:0.0}) over all-retail ({last.RetailOps:0.0}); the same on every run")),
            Timed($"scene {landblock}: all-retail partitioned / exhaustive, ns per position", r => r.RetailNs / r.ExhaustiveNs, PartitionTarget,
                Invariant($"median time per mover position, every object as retail asked of the land cells the mover reaches ({last.RetailNs:0.0} ns in the last run) over asked of every object and cell ({last.ExhaustiveNs:0.0} ns), measured by the scene command interleaved")),
            new($"scene {landblock}: all-retail partitioned / exhaustive, counted operations", last.RetailOps / last.ExhaustiveOps, "<=", PartitionTarget,
                Invariant($"counted distance evaluations per mover position, partitioned ({last.RetailOps:0.0}) over exhaustive ({last.ExhaustiveOps:0.0}); the same on every run; no broad phase goes under the narrow phase's own {last.NarrowFloorOps:0.0} ({last.NarrowFloorOps / last.ExhaustiveOps:0.000} of exhaustive)")),
        ];
    }

    private static double Median(IEnumerable<double> values)
    {
        var sorted = values.Order().ToArray();
        return sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[sorted.Length / 2 - 1] + sorted[sorted.Length / 2]) / 2;
    }

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
