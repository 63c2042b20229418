using static AcShadow.Core.Chart.Output.ChartFormat;

namespace AcShadow.Core.Chart.Output;

/// <summary>
/// failure-map-&lt;id&gt;.svg: the object seen from above at walking height, one panel per model. Each grid
/// probe of the walking-height layer is a cell, each doorway-line probe a dot, coloured by verdict against
/// the reference: both block, both clear, false pass (reference blocks, model lets through), false block.
/// </summary>
public static class FailureMapSvg
{
    private const double PanelPlot = 360, PanelGapX = 70, PanelGapY = 96, Left = 70, Top = 172, Columns = 3;

    public static string FileName(uint setupId) => $"failure-map-{Id(setupId)}.svg";

    public static string Write(ChartReport report, ObjectChart chart)
    {
        var walk = report.Options.EffectiveWalkHeight;
        var slice = Enumerable.Range(0, chart.Probes.Count)
            .Where(i => chart.Probes[i].Kind == ProbeKind.Doorway
                || (chart.Probes[i].Kind == ProbeKind.Grid && MathF.Abs(chart.Probes[i].Center.Z - walk) < 1e-3f))
            .ToArray();
        var half = chart.GridSpacing / 2;
        double minX = double.MaxValue, maxX = double.MinValue, minY = double.MaxValue, maxY = double.MinValue;
        foreach (var i in slice)
        {
            var c = chart.Probes[i].Center;
            minX = Math.Min(minX, c.X - half); maxX = Math.Max(maxX, c.X + half);
            minY = Math.Min(minY, c.Y - half); maxY = Math.Max(maxY, c.Y + half);
        }
        if (slice.Length == 0) { minX = minY = -1; maxX = maxY = 1; }
        var scale = PanelPlot / Math.Max(maxX - minX, maxY - minY);
        double plotW = (maxX - minX) * scale, plotH = (maxY - minY) * scale;
        var models = chart.Models.Count;
        var columns = (int)Math.Min(Columns, models);
        var rows = (models + columns - 1) / columns;
        var width = Left + columns * (plotW + PanelGapX) + 20;
        var height = Top + rows * (plotH + PanelGapY) + 10;
        var svg = new SvgDocument(Math.Max(width, 760), height);

        svg.Text(20, 30, $"Setup {Id(chart.SetupId)}: where each model disagrees with {report.Reference}, seen from above at walking height", 17, "start", "bold");
        svg.Text(20, 52,
            $"slice z = {F(walk, 2)} m (centre of a {F(report.Options.ProbeRadius, 2)} m probe standing on z = 0); cells: grid probes every {F(chart.GridSpacing, 2)} m; framed strips: doorway lines",
            12.5);
        Legend(svg, 20, 84);

        for (var m = 0; m < models; m++)
        {
            var outcome = chart.Models[m];
            var px = Left + (m % columns) * (plotW + PanelGapX);
            var py = Top + (m / columns) * (plotH + PanelGapY);
            double X(double x) => px + (x - minX) * scale;
            double Y(double y) => py + (maxY - y) * scale;

            var slicePass = slice.Count(i => chart.Reference[i] && !outcome.Answers[i]);
            var sliceBlock = slice.Count(i => !chart.Reference[i] && outcome.Answers[i]);
            svg.Text(px, py - 30, outcome.Model + (m == 0 ? " (reference)" : ""), 14, "start", "bold", ChartPalette.Model(m));
            svg.Text(px, py - 14,
                $"{F(outcome.AgreementPercent, 2)}% agree overall; here: {I(slicePass)} false pass, {I(sliceBlock)} false block", 11.5);
            svg.Rect(px, py, plotW, plotH, "#ffffff", ChartPalette.Axis);

            foreach (var i in slice)
            {
                var p = chart.Probes[i];
                if (p.Kind != ProbeKind.Grid) continue;
                svg.Rect(X(p.Center.X - half), Y(p.Center.Y + half), chart.GridSpacing * scale, chart.GridSpacing * scale,
                    Colour(chart.Reference[i], outcome.Answers[i]), "#ffffff", 0.3);
            }
            // Doorway lines: a strip of one cell per probe (step long, 5 px wide), coloured by verdict, framed in black.
            foreach (var line in slice.Where(i => chart.Probes[i].Kind == ProbeKind.Doorway).GroupBy(i => chart.Probes[i].Line))
            {
                var stripe = 6.0;
                var along = report.Options.DoorwayStep * scale;
                var acrossIsY = chart.Doorway?.AcrossIsY ?? true;
                double x0 = double.MaxValue, y0 = double.MaxValue, x1 = double.MinValue, y1 = double.MinValue;
                foreach (var i in line)
                {
                    var c = chart.Probes[i].Center;
                    var (w, hgt) = acrossIsY ? (stripe, along) : (along, stripe);
                    var (rx, ry) = (X(c.X) - w / 2, Y(c.Y) - hgt / 2);
                    svg.Rect(rx, ry, w, hgt, Colour(chart.Reference[i], outcome.Answers[i]));
                    x0 = Math.Min(x0, rx); y0 = Math.Min(y0, ry); x1 = Math.Max(x1, rx + w); y1 = Math.Max(y1, ry + hgt);
                }
                svg.Rect(x0, y0, x1 - x0, y1 - y0, "none", "#000000", 0.5);
            }
            Axes(svg, px, py, plotW, plotH, minX, maxX, minY, maxY, X, Y);
        }
        return svg.Render();
    }

    private static string Colour(bool reference, bool model) => (reference, model) switch
    {
        (true, true) => ChartPalette.AgreeBlocked,
        (false, false) => ChartPalette.AgreeClear,
        (true, false) => ChartPalette.FalsePass,
        _ => ChartPalette.FalseBlock,
    };

    private static void Legend(SvgDocument svg, double x, double y)
    {
        (string Colour, string Label)[] items =
        [
            (ChartPalette.AgreeBlocked, "both block"), (ChartPalette.AgreeClear, "both clear"),
            (ChartPalette.FalsePass, "false pass: reference blocks, model lets through"), (ChartPalette.FalseBlock, "false block: model blocks, reference clear"),
        ];
        foreach (var (colour, label) in items)
        {
            svg.Rect(x, y - 11, 14, 14, colour, "#777777", 0.5);
            svg.Text(x + 19, y, label, 12);
            x += 40 + label.Length * 7.0;
        }
        svg.Text(20, y + 24, "Framed strips: the doorway lines (probes across the opening at walking height, one per lateral offset), coloured the same way.", 12);
    }

    private static void Axes(SvgDocument svg, double px, double py, double w, double h, double minX, double maxX, double minY, double maxY,
        Func<double, double> X, Func<double, double> Y)
    {
        var step = NiceStep(Math.Max(maxX - minX, maxY - minY) / 5);
        for (var t = Math.Ceiling(minX / step) * step; t <= maxX + 1e-9; t += step)
        {
            svg.Line(X(t), py + h, X(t), py + h + 5, ChartPalette.Axis);
            svg.Text(X(t), py + h + 18, F(t, step < 1 ? 1 : 0), 10.5, "middle");
        }
        for (var t = Math.Ceiling(minY / step) * step; t <= maxY + 1e-9; t += step)
        {
            svg.Line(px - 5, Y(t), px, Y(t), ChartPalette.Axis);
            svg.Text(px - 8, Y(t) + 4, F(t, step < 1 ? 1 : 0), 10.5, "end");
        }
        svg.Text(px + w / 2, py + h + 34, "x (m)", 11.5, "middle");
        svg.Text(px - 40, py + h / 2, "y (m)", 11.5, "middle", rotate: -90);
    }

    private static double NiceStep(double raw)
    {
        var magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        var f = raw / magnitude;
        return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * magnitude;
    }
}
