using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// failure-map-&lt;id&gt;.svg: the object seen from above at walking height, one panel per model. Each grid
/// probe of the walking-height layer is a cell, each doorway-line probe a dot, coloured by verdict against
/// the reference: both block, both clear, false pass (reference blocks, model lets through), false block.
/// A layer wider than <see cref="MaxCellsPerSide"/> cells (a huge or flat object, whose whole grid may lie
/// in this one layer) is drawn with k × k probes merged into one cell showing its worst verdict: a panel is
/// 360 px, and finer cells would not show. Neighbouring cells of a row with one verdict are one rectangle:
/// on 100 Setups of the scale dat a map is 88 kB on average, against 810 kB at one rectangle per cell.
/// </summary>
public static class FailureMapSvg
{
    private const double PanelPlot = 360, PanelGapX = 70, PanelGapY = 96, Left = 70, Top = 172, Columns = 3;

    /// <summary>Cells drawn at most along a panel's side (4 px each); more grid probes than that are merged.</summary>
    public const int MaxCellsPerSide = 90;

    public static string FileName(uint setupId) => $"failure-map-{Id(setupId)}.svg";

    /// <summary>Every failure map's name matches this (for finding an earlier run's).</summary>
    public const string FilePattern = "failure-map-*.svg";

    public static string Write(ChartOptions options, string reference, ObjectChart chart)
    {
        var walk = options.EffectiveWalkHeight;
        var slice = Enumerable.Range(0, chart.Probes.Count)
            .Where(i => chart.Probes[i].Kind == ProbeKind.Doorway
                || (chart.Probes[i].Kind == ProbeKind.Grid && MathF.Abs(chart.Probes[i].Center.Z - walk) < 1e-3f))
            .ToArray();
        var half = chart.GridSpacing / 2;
        var grid = MergeFactor(chart, slice);
        var merge = grid.Merge;
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

        svg.Text(20, 30, $"Setup {Id(chart.SetupId)}: where each model disagrees with {reference}, seen from above at walking height", 17, "start", "bold");
        svg.Text(20, 52,
            $"slice z = {F(walk, 2)} m (centre of a {F(options.ProbeRadius, 2)} m probe standing on z = 0); cells: grid probes every {F(chart.GridSpacing, 2)} m" +
            (merge > 1 ? $", {I(merge)} × {I(merge)} per cell (worst verdict shown: false pass, false block, both block, both clear)" : "") + "; framed strips: doorway lines",
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
            svg.Text(px, py - 30, outcome.Model + (m == 0 ? " (reference)" : ""), 14, "start", "bold", DrawingPalette.Model(outcome.Model));
            svg.Text(px, py - 14,
                $"{F(outcome.AgreementPercent, 2)}% agree overall; here: {I(slicePass)} false pass, {I(sliceBlock)} false block", 11.5);
            svg.Rect(px, py, plotW, plotH, "#ffffff", DrawingPalette.Axis);

            // A row's neighbouring cells of one verdict are drawn as one rectangle: the same picture in about a
            // ninth of the bytes, which matters when a whole dat's maps are written.
            var side = (double)chart.GridSpacing * merge;
            foreach (var (row, first, last, verdict) in Runs(MergedCells(chart, slice, outcome.Answers, grid)))
            {
                double x0 = grid.Left + first * side, y1 = grid.Top - row * side;
                double x1 = Math.Min(grid.Left + (last + 1) * side, maxX), y0 = Math.Max(y1 - side, minY);
                svg.Rect(X(x0), Y(y1), (x1 - x0) * scale, (y1 - y0) * scale, MergedColours[verdict]);
            }
            // Doorway lines: a strip of one cell per probe (step long, 5 px wide), coloured by verdict, framed in black.
            foreach (var line in slice.Where(i => chart.Probes[i].Kind == ProbeKind.Doorway).GroupBy(i => chart.Probes[i].Line))
            {
                var stripe = 6.0;
                var along = options.DoorwayStep * scale;
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

    /// <summary>
    /// How many grid probes along each side one drawn cell stands for (1 unless the layer is wider than
    /// <see cref="MaxCellsPerSide"/>), and the layer's top-left corner the merged cells are counted from.
    /// </summary>
    private static (int Merge, double Left, double Top) MergeFactor(ObjectChart chart, int[] slice)
    {
        double minX = double.MaxValue, maxX = double.MinValue, minY = double.MaxValue, maxY = double.MinValue;
        foreach (var i in slice)
        {
            if (chart.Probes[i].Kind != ProbeKind.Grid) continue;
            var c = chart.Probes[i].Center;
            minX = Math.Min(minX, c.X); maxX = Math.Max(maxX, c.X);
            minY = Math.Min(minY, c.Y); maxY = Math.Max(maxY, c.Y);
        }
        if (minX > maxX) return (1, 0, 0);
        var half = (double)chart.GridSpacing / 2;
        var cells = Math.Max(maxX - minX, maxY - minY) / chart.GridSpacing + 1;
        return (cells <= MaxCellsPerSide ? 1 : (int)Math.Ceiling(cells / MaxCellsPerSide), minX - half, maxY + half);
    }

    /// <summary>
    /// Each merged cell (counted from the layer's top-left corner, x right, y down) with its worst verdict:
    /// 3 false pass, 2 false block, 1 both block, 0 both clear; in row order, so the bytes are the same every run.
    /// </summary>
    private static IEnumerable<((long X, long Y) Cell, int Verdict)> MergedCells(ObjectChart chart, int[] slice, bool[] answers, (int Merge, double Left, double Top) grid)
    {
        var cells = new Dictionary<(long X, long Y), int>();
        foreach (var i in slice)
        {
            var p = chart.Probes[i];
            if (p.Kind != ProbeKind.Grid) continue;
            var key = ((long)Math.Floor((p.Center.X - grid.Left) / chart.GridSpacing) / grid.Merge,
                       (long)Math.Floor((grid.Top - p.Center.Y) / chart.GridSpacing) / grid.Merge);
            var verdict = (chart.Reference[i], answers[i]) switch { (true, false) => 3, (false, true) => 2, (true, true) => 1, _ => 0 };
            cells[key] = Math.Max(cells.GetValueOrDefault(key), verdict);
        }
        return cells.OrderBy(c => c.Key.Y).ThenBy(c => c.Key.X).Select(c => (c.Key, c.Value));
    }

    /// <summary>Cells in row order as runs: (row, first column, last column, verdict) of neighbouring cells with one verdict.</summary>
    private static IEnumerable<(long Row, long First, long Last, int Verdict)> Runs(IEnumerable<((long X, long Y) Cell, int Verdict)> cells)
    {
        (long Row, long First, long Last, int Verdict)? open = null;
        foreach (var ((x, y), verdict) in cells)
        {
            if (open is { } o && o.Row == y && o.Last + 1 == x && o.Verdict == verdict)
            {
                open = o with { Last = x };
                continue;
            }
            if (open is { } done) yield return done;
            open = (y, x, x, verdict);
        }
        if (open is { } rest) yield return rest;
    }

    private static readonly string[] MergedColours = [DrawingPalette.AgreeClear, DrawingPalette.AgreeBlocked, DrawingPalette.FalseBlock, DrawingPalette.FalsePass];

    private static string Colour(bool reference, bool model) => (reference, model) switch
    {
        (true, true) => DrawingPalette.AgreeBlocked,
        (false, false) => DrawingPalette.AgreeClear,
        (true, false) => DrawingPalette.FalsePass,
        _ => DrawingPalette.FalseBlock,
    };

    private static void Legend(SvgDocument svg, double x, double y)
    {
        (string Colour, string Label)[] items =
        [
            (DrawingPalette.AgreeBlocked, "both block"), (DrawingPalette.AgreeClear, "both clear"),
            (DrawingPalette.FalsePass, "false pass: reference blocks, model lets through"), (DrawingPalette.FalseBlock, "false block: model blocks, reference clear"),
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
            svg.Line(X(t), py + h, X(t), py + h + 5, DrawingPalette.Axis);
            svg.Text(X(t), py + h + 18, F(t, step < 1 ? 1 : 0), 10.5, "middle");
        }
        for (var t = Math.Ceiling(minY / step) * step; t <= maxY + 1e-9; t += step)
        {
            svg.Line(px - 5, Y(t), px, Y(t), DrawingPalette.Axis);
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
