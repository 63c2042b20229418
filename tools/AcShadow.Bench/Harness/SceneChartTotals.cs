using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>
/// The three landblock rows of a scene-chart.csv `acshadow scene` wrote: the whole scene's median time and
/// counted operations per mover position, every object as retail and as compiled (both through the
/// land-cell partition), and every object as retail asked of every object and cell (the exhaustive walk).
/// </summary>
public sealed record SceneChartTotals(double RetailNs, double CompiledNs, double RetailOps, double CompiledOps, double ExhaustiveNs, double ExhaustiveOps)
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
        return new SceneChartTotals(Number(retail, "median_ns"), Number(compiled, "median_ns"), Number(retail, "ops"), Number(compiled, "ops"),
            Number(exhaustive, "median_ns"), Number(exhaustive, "ops"));
    }

    /// <summary>
    /// Compiled over all-retail, per position (below 1: compiling saves), and all-retail through the land-cell
    /// partition over the exhaustive walk: time and counted operations, all measured interleaved in one run.
    /// </summary>
    public IReadOnlyList<Ratio> Ratios(string landblock) =>
    [
        new($"scene {landblock}: compiled / all-retail, ns per position", CompiledNs / RetailNs, "<=", CompiledTarget,
            Invariant($"median time to ask the whole scene about one mover position, compiled ({CompiledNs:0.0} ns) over every object as retail ({RetailNs:0.0} ns), both through the land-cell partition, measured by the scene command interleaved")),
        new($"scene {landblock}: compiled / all-retail, counted operations", CompiledOps / RetailOps, "<=", CompiledTarget,
            Invariant($"counted distance evaluations per mover position, compiled ({CompiledOps:0.0}) over all-retail ({RetailOps:0.0}); the same on every run")),
        new($"scene {landblock}: all-retail partitioned / exhaustive, ns per position", RetailNs / ExhaustiveNs, "<=", PartitionTarget,
            Invariant($"median time per mover position, every object as retail asked of the land cells the mover reaches ({RetailNs:0.0} ns) over asked of every object and cell ({ExhaustiveNs:0.0} ns), measured by the scene command interleaved")),
        new($"scene {landblock}: all-retail partitioned / exhaustive, counted operations", RetailOps / ExhaustiveOps, "<=", PartitionTarget,
            Invariant($"counted distance evaluations per mover position, partitioned ({RetailOps:0.0}) over exhaustive ({ExhaustiveOps:0.0}); the same on every run")),
    ];

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
