using System.Numerics;
using System.Text;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Fixtures.Movement;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// movement-map-&lt;id&gt;.svg: the object's movement cases seen from above, one panel per model (the reference
/// excepted) and state. Each case is a start line, from where the walk starts to where it aims, coloured by the
/// model's verdict; a hollow dot marks where the reference's walk ended, a filled one (verdict colour) where the
/// model's did; the dashed line is the gate. The reference's outline is grey, the model's in its colour.
/// </summary>
public static class MovementMapSvg
{
    private const double Panel = 300, GapX = 40, GapY = 78, Left = 30, Top = 150;
    private const int Columns = 4;

    public static string FileName(uint setupId) => $"movement-map-{Id(setupId)}.svg";

    public static string Write(ObjectMovementChart chart)
    {
        var cases = chart.Cases;
        double minX = chart.FootprintMin.X, minY = chart.FootprintMin.Y, maxX = chart.FootprintMax.X, maxY = chart.FootprintMax.Y;
        void Add(Vector3 p)
        {
            minX = Math.Min(minX, p.X); maxX = Math.Max(maxX, p.X);
            minY = Math.Min(minY, p.Y); maxY = Math.Max(maxY, p.Y);
        }
        foreach (var c in cases)
        {
            Add(c.Walk.Start);
            Add(Aim(c.Walk));
        }
        const double pad = 0.3;
        minX -= pad; minY -= pad; maxX += pad; maxY += pad;

        var panels = new List<(int Model, string State)>();
        foreach (var state in chart.States)
            for (var m = 1; m < chart.Models.Count; m++) panels.Add((m, state));
        var probe = new FloorPanel(0, 0, Panel, minX, minY, maxX, maxY);
        var columns = Math.Max(1, Math.Min(Columns, panels.Count));
        var rows = (panels.Count + columns - 1) / columns;
        var svg = new SvgDocument(Math.Max(Left + columns * (probe.Width + GapX), 900), Top + rows * (probe.Height + GapY) + 10);

        var reference = chart.Models[0];
        svg.Text(20, 30, $"Setup {Id(chart.SetupId)}: each model's walks against the {reference.Model} reference's, seen from above", 17, "start", "bold");
        svg.Text(20, 52, $"{I(cases.Count)} walks ({I(chart.Fragile.Count(f => f))} fragile); line: from the start to where the walk aims, coloured by verdict; hollow dot: the reference's end; filled dot: the model's end; dashed: the gate", 12);
        var lx = 20.0;
        foreach (var verdict in MovementVerdicts.All)
        {
            svg.Rect(lx, 72, 14, 14, DrawingPalette.Verdict(verdict));
            svg.Text(lx + 20, 84, MovementVerdicts.Name(verdict).Replace('_', ' '), 12);
            lx += 150;
        }
        svg.Text(20, 112, "Verdicts (movement.md §4.2), first match: false pass (crosses where the reference does not, overlaps retail's geometry, or gets past a blocking face), false block, deflection, step mismatch, stand-off drift.", 11);

        for (var k = 0; k < panels.Count; k++)
        {
            var (m, state) = panels[k];
            var model = chart.Models[m];
            var px = Left + (k % columns) * (probe.Width + GapX);
            var py = Top + (k / columns) * (probe.Height + GapY);
            var panel = new FloorPanel(px, py, Panel, minX, minY, maxX, maxY);
            var inState = Enumerable.Range(0, cases.Count).Where(i => cases[i].State == state).ToArray();
            var counts = MovementVerdicts.All.Skip(1).Select(v => (v, inState.Count(i => model.Verdicts[i] == v))).Where(c => c.Item2 > 0)
                .Select(c => $"{I(c.Item2)} {MovementVerdicts.Name(c.v).Replace('_', ' ')}").ToArray();
            svg.Text(px, py - 24, $"{model.Model} · {state}", 14, "start", "bold", DrawingPalette.Model(model.Model));
            svg.Text(px, py - 8, counts.Length == 0 ? $"all {I(inState.Length)} walks agree" : string.Join(", ", counts), 11);
            panel.Outline(svg, chart.Outlines[0], "#d0d0d0", 0.5, "#909090");
            panel.Outline(svg, chart.Outlines[m], DrawingPalette.Model(model.Model), 0.25, DrawingPalette.Model(model.Model));
            foreach (var gate in inState.Select(i => cases[i].Gate).Distinct()) panel.Gate(svg, gate, "#444444");
            // Agreement first, so the verdicts that matter are drawn on top.
            foreach (var verdict in MovementVerdicts.All)
            {
                var lines = new StringBuilder();
                var ends = new StringBuilder();
                foreach (var i in inState.Where(i => model.Verdicts[i] == verdict))
                {
                    panel.Segment(lines, cases[i].Walk.Start, Aim(cases[i].Walk));
                    panel.Dot(ends, model.Ends[i], 1.6);
                }
                var colour = DrawingPalette.Verdict(verdict);
                svg.Path(lines.ToString(), "none", colour, verdict == MovementVerdict.Agree ? 0.6 : 1.1, verdict == MovementVerdict.Agree ? 0.5 : 0.85);
                svg.Path(ends.ToString(), colour);
            }
            var referenceEnds = new StringBuilder();
            foreach (var i in inState) panel.Dot(referenceEnds, MovementJudge.End(cases[i].Walk, cases[i].Expected), 2.2);
            svg.Path(referenceEnds.ToString(), "none", "#000000", 0.6);
            panel.Frame(svg);
        }
        return svg.Render();
    }

    /// <summary>Where the walk aims: its start plus its velocity over all its frames.</summary>
    internal static Vector3 Aim(Walk walk) => walk.Start + walk.Velocity * (walk.Quantum * walk.Frames);
}
