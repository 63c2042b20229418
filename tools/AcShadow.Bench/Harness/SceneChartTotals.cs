using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>
/// The two landblock rows of a scene-chart.csv `acshadow scene` wrote: the whole scene's median time and
/// counted operations per mover position, every object as retail and as compiled.
/// </summary>
public sealed record SceneChartTotals(double RetailNs, double CompiledNs, double RetailOps, double CompiledOps)
{
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
        return new SceneChartTotals(Number(retail, "median_ns"), Number(compiled, "median_ns"), Number(retail, "ops"), Number(compiled, "ops"));
    }

    /// <summary>Compiled over all-retail, per position: time and counted operations (below 1: compiling saves).</summary>
    public IReadOnlyList<Ratio> Ratios(string landblock) =>
    [
        new($"scene {landblock}: compiled / all-retail, ns per position", CompiledNs / RetailNs, "<=", 1,
            Invariant($"median time to ask the whole scene about one mover position, compiled ({CompiledNs:0.0} ns) over every object as retail ({RetailNs:0.0} ns), measured by the scene command interleaved")),
        new($"scene {landblock}: compiled / all-retail, counted operations", CompiledOps / RetailOps, "<=", 1,
            Invariant($"counted distance evaluations per mover position, compiled ({CompiledOps:0.0}) over all-retail ({RetailOps:0.0}); the same on every run")),
    ];

    private static string Invariant(FormattableString s) => s.ToString(CultureInfo.InvariantCulture);
}
