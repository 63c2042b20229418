using System.Globalization;
using System.Text;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// scene-chart.csv: first the landblock as a whole, once with every object as retail and once compiled
/// (positions asked, agreement with all-retail, median time and counted operations per mover position),
/// both through the land-cell partition, then all-retail asked of every object and cell (the old walk),
/// then the narrow-phase floor (counted operations only: what no broad phase in front of all-retail can save),
/// then one row per placed object (its chosen model, its probes and disagreements, time and counted
/// operations per query of the chosen model and of retail),
/// then one per indoor cell (always retail: its probes are where the scene was checked around it).
/// </summary>
internal static class SceneChartCsv
{
    public const string Header =
        "scope,index,id,model,shapes,probes,agree,agreement_pct,false_pass,false_block,median_ns,p10_ns,p90_ns,retail_median_ns,ops,retail_ops";

    /// <summary>The model column of the exhaustive walk's row: all-retail, every object and cell asked at every position.</summary>
    public const string ExhaustiveModel = "all-retail-exhaustive";

    /// <summary>The model column of the narrow-phase floor's row (<see cref="SceneWalk.NarrowFloor"/>): counted, never timed.</summary>
    public const string NarrowFloorModel = "all-retail-narrow-floor";

    public static string Write(CompiledSceneReport report)
    {
        var t = report.Totals;
        var csv = new StringBuilder(Header).Append('\n');
        Row(csv, "landblock", "", "", "all-retail", t.RetailShapes, t.Positions, t.Positions, 100, 0, 0, t.Retail.MedianNs, t.Retail.P10Ns, t.Retail.P90Ns, t.Retail.MedianNs, t.RetailOps, t.RetailOps);
        Row(csv, "landblock", "", "", "compiled", t.CompiledShapes, t.Positions, t.Agree, t.AgreementPercent, t.FalsePass, t.FalseBlock, t.Compiled.MedianNs, t.Compiled.P10Ns, t.Compiled.P90Ns, t.Retail.MedianNs, t.CompiledOps, t.RetailOps);
        // The walk the land-cell partition replaced: the same answers, every object and cell asked.
        Row(csv, "landblock", "", "", ExhaustiveModel, t.RetailShapes, t.Positions, t.Positions, 100, 0, 0, t.Exhaustive.MedianNs, t.Exhaustive.P10Ns, t.Exhaustive.P90Ns, t.Retail.MedianNs, t.ExhaustiveOps, t.RetailOps);
        Row(csv, "landblock", "", "", NarrowFloorModel, t.RetailShapes, t.Positions, t.Positions, 100, 0, 0, double.NaN, double.NaN, double.NaN, t.Retail.MedianNs, t.NarrowFloorOps, t.RetailOps);
        foreach (var placed in report.Placed.Select(p => p.Object))
        {
            var c = report.For(placed);
            var probes = c?.Probes.Count ?? 0;
            var agree = probes - (c?.FalsePass ?? 0) - (c?.FalseBlock ?? 0);
            Row(csv, "object", I(placed.Index), JsonIds.Format(placed.Id), c?.Model ?? ObjectCompilation.UnresolvedLabel, c?.Chosen?.Shapes.Count ?? 0, probes, agree,
                probes == 0 ? 100 : 100.0 * agree / probes, c?.FalsePass ?? 0, c?.FalseBlock ?? 0,
                c?.ChosenTiming.MedianNs ?? double.NaN, c?.ChosenTiming.P10Ns ?? double.NaN, c?.ChosenTiming.P90Ns ?? double.NaN, c?.RetailTiming.MedianNs ?? double.NaN,
                c is null || c.Probes.Count == 0 ? double.NaN : c.ChosenOps, c is null || c.Probes.Count == 0 ? double.NaN : c.RetailOps);
        }
        foreach (var cell in report.Cells)
            Row(csv, "cell", "", JsonIds.Format(cell.Cell.Id), cell.Bsp is null ? ObjectCompilation.UnresolvedLabel : CellCompilation.Model, cell.Bsp is null ? 0 : 1,
                cell.Probes.Count, cell.Probes.Count, 100, 0, 0, double.NaN, double.NaN, double.NaN, double.NaN, double.NaN, double.NaN);
        return csv.ToString();
    }

    private static void Row(StringBuilder csv, string scope, string index, string id, string model, int shapes, int probes, int agree, double pct,
        int falsePass, int falseBlock, double median, double p10, double p90, double retail, double ops, double retailOps) =>
        csv.Append(string.Join(',', scope, index, id, model, I(shapes), I(probes), I(agree), F(pct, 3), I(falsePass), I(falseBlock),
            F(median, 1), F(p10, 1), F(p90, 1), F(retail, 1), F(ops, 3), F(retailOps, 3))).Append('\n');

    private static string I(long v) => v.ToString(CultureInfo.InvariantCulture);

    private static string F(double v, int decimals) =>
        double.IsFinite(v) ? v.ToString("F" + decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture) : "";
}
