using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// scene-chart.svg: what modelling less costs and saves for one landblock. Top: the time to ask the whole
/// scene about one mover position with every object as retail and as compiled (median bar, p10–p90
/// whisker) and how often the two agree. Below: one row per placed object, its chosen model, its time per
/// query against retail's, and its disagreements over its own probes.
/// </summary>
internal static class SceneChartSvg
{
    private const double Width = 1100, Left = 330, BarWidth = 560, Row = 24;

    public static string Write(CompiledSceneReport report)
    {
        var t = report.Totals;
        var objects = report.Placed.Select(p => p.Object).ToArray();
        var height = 250 + (objects.Length + report.Cells.Count) * Row + 60;
        var svg = new SvgDocument(Width, height);
        svg.Text(20, 30, $"Landblock {JsonIds.Format(report.Scene.LandBlockInfoId)}: every object as retail against the compiled scene", 18, "start", "bold");
        svg.Text(20, 52, $"{I(objects.Length)} placed object(s), {I(report.Cells.Count)} indoor cell(s) (retail in both); {I(t.Positions)} mover positions (every object's and cell's probes, in the landblock); mover radius {string.Join(", ", report.Options.Chart.Radii.Select(r => F(r, 2) + " m"))}; tolerance {F(report.Options.TolerancePercent, 2)} % false blocks, no false pass", 12.5);

        var top = Math.Max(Max(t.Retail.P90Ns), Max(t.Compiled.P90Ns));
        double X(double ns, double scale) => Left + (double.IsFinite(ns) ? Math.Clamp(ns / scale, 0, 1) : 0) * BarWidth;
        svg.Text(20, 88, "Time to ask the whole scene about one mover position (median, p10–p90)", 14, "start", "bold");
        Bar(svg, 108, "every object as retail", t.Retail, DrawingPalette.AgreeBlocked, top, X, $"{Time(t.Retail.MedianNs)}, {I(t.RetailShapes)} shapes");
        Bar(svg, 140, "compiled", t.Compiled, DrawingPalette.Compiled, top, X,
            $"{Time(t.Compiled.MedianNs)}, {I(t.CompiledShapes)} shapes{Saving(t.Retail.MedianNs, t.Compiled.MedianNs)}");
        var verdict = t.FalsePass == 0 && t.FalseBlock == 0 ? "agrees with every-object-retail on every position" : $"{I(t.FalsePass)} false pass, {I(t.FalseBlock)} false block";
        svg.Text(20, 190, $"Accuracy: compiled {verdict} ({I(t.Agree)} of {I(t.Positions)}, {F(t.AgreementPercent, 3)} %)", 13.5, "start", "bold",
            t.FalsePass > 0 ? DrawingPalette.FalsePass : DrawingPalette.Axis);

        svg.Text(20, 226, "Per object: chosen model, time per query (coloured) against retail (grey), disagreements over its probes", 14, "start", "bold");
        var perObject = objects.Select(report.For).Where(c => c is not null).SelectMany(c => new[] { c!.ChosenTiming.P90Ns, c.RetailTiming.P90Ns }).Where(double.IsFinite).DefaultIfEmpty(1).Max();
        for (var k = 0; k < objects.Length; k++)
        {
            var placed = objects[k];
            var c = report.For(placed);
            var y = 250 + k * Row;
            svg.Text(20, y + 12, $"#{I(placed.Index)} {JsonIds.Format(placed.Id)} → {c?.Model ?? ObjectCompilation.UnresolvedLabel}", 12, "start", "normal", ModelColour(c?.Model));
            if (c is null || c.Probes.Count == 0) continue;
            svg.Rect(Left, y + 2, X(c.RetailTiming.MedianNs, perObject) - Left, 8, DrawingPalette.AgreeBlocked, title: $"retail {Time(c.RetailTiming.MedianNs)}");
            svg.Rect(Left, y + 11, X(c.ChosenTiming.MedianNs, perObject) - Left, 8, ModelColour(c.Model), title: $"{c.Model} {Time(c.ChosenTiming.MedianNs)}");
            svg.Text(Left + BarWidth + 10, y + 12, $"{Time(c.ChosenTiming.MedianNs)} vs {Time(c.RetailTiming.MedianNs)}; {I(c.Probes.Count)} probes, {I(c.FalsePass)} false pass, {I(c.FalseBlock)} false block", 10.5);
        }
        for (var k = 0; k < report.Cells.Count; k++)
        {
            var cell = report.Cells[k];
            var y = 250 + (objects.Length + k) * Row;
            svg.Text(20, y + 12, $"cell {JsonIds.Format(cell.Cell.Id)} → {(cell.Bsp is null ? ObjectCompilation.UnresolvedLabel : CellCompilation.Model)}", 12, "start", "normal", ModelColour(cell.Bsp is null ? null : CellCompilation.Model));
            if (cell.Bsp is not null)
                svg.Text(Left, y + 12, $"kept as retail: a room a mover stands inside, which every cheaper (solid) model would fill; {I(cell.Bsp.Polygons.Length)} polygons, {I(cell.Probes.Count)} probes", 10.5);
        }
        svg.Text(20, height - 20, "Times are measurements: they vary with machine, load and build. Disagreements do not.", 11);
        return svg.Render();
    }

    private static void Bar(SvgDocument svg, double y, string label, Chart.TimingStats timing, string colour, double top, Func<double, double, double> x, string value)
    {
        svg.Text(Left - 10, y + 14, label, 13, "end");
        svg.Rect(Left, y, x(timing.MedianNs, top) - Left, 20, colour, title: $"{label}: {Time(timing.MedianNs)} per mover position");
        if (double.IsFinite(timing.P10Ns) && double.IsFinite(timing.P90Ns))
            svg.Line(x(timing.P10Ns, top), y + 10, x(timing.P90Ns, top), y + 10, DrawingPalette.Axis, 1.5);
        svg.Text(Math.Max(x(timing.P90Ns, top), x(timing.MedianNs, top)) + 8, y + 14, value, 12);
    }

    private static string Saving(double retail, double compiled) =>
        double.IsFinite(retail) && double.IsFinite(compiled) && compiled > 0 ? $", {F(retail / compiled, 1)}x faster than all-retail" : "";

    private static double Max(double v) => double.IsFinite(v) && v > 0 ? v : 1;

    private static string ModelColour(string? model) => model is null ? DrawingPalette.Unknown : DrawingPalette.Model(model);
}
