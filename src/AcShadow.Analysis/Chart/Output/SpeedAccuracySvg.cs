using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// speed-accuracy.svg: x = median time per query (log scale, ns), y = agreement with the reference over
/// all probes (%). One labelled dot per model; a horizontal bar from p10 to p90 of its timed batches and a
/// vertical bar from its worst to its best object's agreement. With the movement chart (`chart --movement`), a
/// diamond per model at the same time gives its movement accuracy: the share of non-fragile walks whose verdict
/// is agreement (movement-summary.csv), joined to its dot by a dashed line.
/// </summary>
public static class SpeedAccuracySvg
{
    private const double Width = 1080, Height = 620;
    private const double Left = 90, Right = 400, Top = 78, Bottom = 74;


    public static string Write(ChartOptions options, string reference, int objects, IReadOnlyList<ModelSummary> summaries,
        IReadOnlyList<Movement.MovementSummary>? movement = null)
    {
        var svg = new SvgDocument(Width, Height);
        double plotW = Width - Left - Right, plotH = Height - Top - Bottom;

        var times = summaries.SelectMany(s => new[] { s.Timing.P10Ns, s.Timing.MedianNs, s.Timing.P90Ns }).Where(t => t > 0 && double.IsFinite(t)).ToArray();
        var lo = times.Length == 0 ? 10 : Math.Pow(10, Math.Floor(Math.Log10(times.Min())));
        var hi = times.Length == 0 ? 1e4 : Math.Pow(10, Math.Ceiling(Math.Log10(times.Max())));
        if (hi <= lo) hi = lo * 10;
        var worst = summaries.Select(s => Math.Min(s.AgreementPercent, s.MinObjectAgreement))
            .Concat(movement?.Select(s => s.AgreementPercent) ?? []).Where(double.IsFinite).DefaultIfEmpty(100).Min();
        var yMin = Math.Min(90, Math.Max(0, Math.Floor(worst / 10) * 10));
        var yStep = (100 - yMin) <= 10 ? 2 : (100 - yMin) <= 30 ? 5 : 10;

        double X(double ns) => Left + (Math.Log10(Math.Clamp(ns, lo, hi)) - Math.Log10(lo)) / (Math.Log10(hi) - Math.Log10(lo)) * plotW;
        // Headroom above 100% so the labels of exact models stay inside the plot.
        var yTop = 100 + (100 - yMin) * 0.08;
        double Y(double pct) => Top + (yTop - Math.Clamp(pct, yMin, 100)) / (yTop - yMin) * plotH;

        svg.Text(Width / 2, 30, $"Speed against accuracy: each model against the {reference} reference", 18, "middle", "bold");
        var probes = summaries.Count > 0 ? summaries[0].Probes : 0;
        svg.Text(Width / 2, 52,
            $"{I(objects)} object(s), {I(probes)} probes per model (probe radius {F(options.ProbeRadius, 2)} m, grid spacing {F(options.Spacing, 2)} m)",
            13, "middle");

        // Axes, decade grid and minor ticks.
        svg.Rect(Left, Top, plotW, plotH, "none", DrawingPalette.Axis);
        for (var decade = lo; decade <= hi * 1.0001; decade *= 10)
        {
            var x = X(decade);
            svg.Line(x, Top, x, Top + plotH, DrawingPalette.GridLine);
            svg.Line(x, Top + plotH, x, Top + plotH + 6, DrawingPalette.Axis);
            svg.Text(x, Top + plotH + 22, Time(decade), 12, "middle");
            for (var k = 2; k <= 9 && decade * k < hi; k++)
                svg.Line(X(decade * k), Top + plotH, X(decade * k), Top + plotH + 3, DrawingPalette.Axis);
        }
        for (var pct = yMin; pct <= 100.0001; pct += yStep)
        {
            var y = Y(pct);
            svg.Line(Left, y, Left + plotW, y, DrawingPalette.GridLine);
            svg.Line(Left - 6, y, Left, y, DrawingPalette.Axis);
            svg.Text(Left - 10, y + 4, F(pct, 0) + "%", 12, "end");
        }
        svg.Text(Left + plotW / 2, Height - 24, "median time per query (log scale; ns = nanoseconds, µs = microseconds)", 13, "middle");
        svg.Text(28, Top + plotH / 2, movement is null ? "agreement with the reference (% of probes)" : "agreement with the reference (● % of probes, ◆ % of walks)", 13, "middle", rotate: -90);

        for (var m = 0; m < summaries.Count; m++)
        {
            var s = summaries[m];
            var colour = DrawingPalette.Model(s.Model);
            var x = X(s.Timing.MedianNs);
            var y = Y(s.AgreementPercent);
            if (double.IsFinite(s.Timing.P10Ns) && double.IsFinite(s.Timing.P90Ns))
            {
                svg.Line(X(s.Timing.P10Ns), y, X(s.Timing.P90Ns), y, colour, 2);
                svg.Line(X(s.Timing.P10Ns), y - 5, X(s.Timing.P10Ns), y + 5, colour, 2);
                svg.Line(X(s.Timing.P90Ns), y - 5, X(s.Timing.P90Ns), y + 5, colour, 2);
            }
            if (double.IsFinite(s.MinObjectAgreement))
            {
                svg.Line(x, Y(s.MinObjectAgreement), x, Y(s.MaxObjectAgreement), colour, 2);
                svg.Line(x - 5, Y(s.MinObjectAgreement), x + 5, Y(s.MinObjectAgreement), colour, 2);
                svg.Line(x - 5, Y(s.MaxObjectAgreement), x + 5, Y(s.MaxObjectAgreement), colour, 2);
            }
            svg.Circle(x, y, 6, colour, "#ffffff", 1.5, $"{s.Model}: {Time(s.Timing.MedianNs)} per query, {F(s.AgreementPercent, 2)}% agreement");
            if (movement is not null && m < movement.Count)
            {
                var my = Y(movement[m].AgreementPercent);
                svg.Line(x, y, x, my, colour, 1.2, "4 3");
                svg.Polygon([(x, my - 7), (x + 7, my), (x, my + 7), (x - 7, my)], colour, 1, "#ffffff", 1.5);
            }
        }
        var labels = new LabelPlacer(Left, Top, Left + plotW, Top + plotH);
        foreach (var s in summaries) labels.Avoid(X(s.Timing.MedianNs), Y(s.AgreementPercent), 7);
        for (var m = 0; m < summaries.Count; m++)
        {
            var s = summaries[m];
            var label = s.FalsePass > 0 ? $"{s.Model} ({I(s.FalsePass)} false passes)" : s.Model;
            var (tx, ty, anchor) = labels.Place(X(s.Timing.MedianNs), Y(s.AgreementPercent), label.Length * 7.4, 14);
            svg.Text(tx, ty, label, 12, anchor, "bold", DrawingPalette.Model(s.Model));
        }

        // Legend.
        var lx = Left + plotW + 24;
        var ly = Top + 6;
        svg.Text(lx, ly, "Models", 14, "start", "bold");
        var rowHeight = movement is null ? 40 : 54;
        for (var m = 0; m < summaries.Count; m++)
        {
            var s = summaries[m];
            var row = ly + 24 + m * rowHeight;
            svg.Circle(lx + 7, row - 4, 6, DrawingPalette.Model(s.Model), "#ffffff", 1.5);
            svg.Text(lx + 20, row, s.Model + (m == 0 ? " (reference)" : ""), 13, "start", "bold", DrawingPalette.Model(s.Model));
            svg.Text(lx + 20, row + 16, $"{Time(s.Timing.MedianNs)}/query, {F(s.AgreementPercent, 2)}% agree, {I(s.FalsePass)} false pass, {I(s.FalseBlock)} false block", 10.5);
            if (movement is not null && m < movement.Count)
                svg.Text(lx + 20, row + 30, $"walks: {F(movement[m].AgreementPercent, 2)}% agree, {I(movement[m].Counts[(int)Movement.MovementVerdict.FalsePass] + movement[m].FragileFalsePass)} false pass, {Time(movement[m].NsPerTransition)}/transition", 10.5);
        }
        var ny = ly + 24 + summaries.Count * rowHeight + 10;
        svg.Text(lx, ny, "dot: median time, agreement over all probes", 11);
        svg.Text(lx, ny + 16, "horizontal bar: p10–p90 time over timed batches", 11);
        svg.Text(lx, ny + 32, "vertical bar: worst–best object agreement", 11);
        svg.Text(lx, ny + 48, "false pass: reference blocks, model lets through", 11);
        if (movement is not null) svg.Text(lx, ny + 64, "diamond: walks judged agreement (movement.md §4.2)", 11);
        return svg.Render();
    }
}
