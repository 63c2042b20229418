using System.Numerics;
using System.Text;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Fixtures.Movement;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// movement-walk-&lt;id&gt;-&lt;model&gt;.svg (`chart --movement --walk CASE`): one walk seen from above, the model's
/// frames against the reference's: the reference's outline grey, the model's in its colour, the gate dashed,
/// the reference's path black and the model's in its verdict's colour, a dot per frame end, with what each did.
/// </summary>
public static class MovementWalkSvg
{
    private const double Panel = 460, Left = 30, Top = 150;

    public static string FileName(uint setupId, string model) => $"movement-walk-{Id(setupId)}-{model}.svg";

    /// <summary>One drawing per model (the reference included), in model order; none when the chart kept no walk.</summary>
    public static IEnumerable<(string Model, string Svg)> Write(ObjectMovementChart chart)
    {
        if (chart.Walk is not { } walk) yield break;
        var referenceFrames = chart.Cases[walk.Case].Expected;
        for (var m = 0; m < chart.Models.Count; m++)
            yield return (chart.Models[m].Model, Draw(chart, walk.Case, referenceFrames, walk.Frames[m], m));
    }

    private static string Draw(ObjectMovementChart chart, int index, IReadOnlyList<MovementFrame> reference, IReadOnlyList<MovementFrame> frames, int m)
    {
        var c = chart.Cases[index];
        var model = chart.Models[m];
        var verdict = model.Verdicts[index];
        double minX = chart.FootprintMin.X - 1, minY = chart.FootprintMin.Y - 1, maxX = chart.FootprintMax.X + 1, maxY = chart.FootprintMax.Y + 1;
        foreach (var p in reference.Select(f => f.Position).Concat(frames.Select(f => f.Position)).Append(c.Walk.Start))
        {
            minX = Math.Min(minX, p.X - 0.5); maxX = Math.Max(maxX, p.X + 0.5);
            minY = Math.Min(minY, p.Y - 0.5); maxY = Math.Max(maxY, p.Y + 0.5);
        }
        var panel = new FloorPanel(Left, Top, Panel, minX, minY, maxX, maxY);
        var svg = new SvgDocument(Math.Max(Left + panel.Width + 30, 1000), Top + panel.Height + 40);
        var r = c.Outcome;
        var o = MovementOutcome.Of(c.Walk, frames, c.Gate);
        svg.Text(20, 30, $"Setup {Id(chart.SetupId)}, walk {c.Id}: {model.Model}", 17, "start", "bold", DrawingPalette.Model(model.Model));
        svg.Text(20, 54, $"{model.Model}: {Did(o)}; verdict {MovementVerdicts.Name(verdict).Replace('_', ' ')}", 13, "start", "bold", DrawingPalette.Verdict(verdict));
        svg.Text(20, 74, $"{chart.Models[0].Model} (black): {Did(r)}", 13);
        svg.Text(20, 98, $"{I(frames.Count)} frames of {F(c.Walk.Quantum * 1000, 1)} ms at {F(new Vector2(c.Walk.Velocity.X, c.Walk.Velocity.Y).Length(), 2)} m/s; a dot per frame end (the model's wide and coloured, the reference's black over it); grey: {chart.Models[0].Model}'s outline; dashed: the gate", 11.5);
        svg.Text(20, 116, $"{model.Model}'s events: {Events(frames, c.Walk)}; {chart.Models[0].Model}'s: {Events(reference, c.Walk)}; grid 1 m, north up", 11.5);
        for (var x = Math.Ceiling(minX); x <= maxX; x++) svg.Line(panel.X(x), panel.Y(minY), panel.X(x), panel.Y(maxY), DrawingPalette.GridLine, 0.6);
        for (var y = Math.Ceiling(minY); y <= maxY; y++) svg.Line(panel.X(minX), panel.Y(y), panel.X(maxX), panel.Y(y), DrawingPalette.GridLine, 0.6);
        panel.Outline(svg, chart.Outlines[0], "#d0d0d0", 0.6, "#808080");
        if (m > 0) panel.Outline(svg, chart.Outlines[m], DrawingPalette.Model(model.Model), 0.3, DrawingPalette.Model(model.Model));
        panel.Gate(svg, c.Gate, "#444444");
        // The model's walk first and wide, the reference's over it, so both show where they coincide.
        if (m > 0) Path(svg, panel, c.Walk.Start, frames, DrawingPalette.Verdict(verdict), 3.2, 2.4);
        Path(svg, panel, c.Walk.Start, reference, "#000000", 1, 1.2);
        svg.Circle(panel.X(c.Walk.Start.X), panel.Y(c.Walk.Start.Y), 4, "#ffffff", "#000000", 1.2, "start");
        panel.Frame(svg);
        return svg.Render();
    }

    private static void Path(SvgDocument svg, FloorPanel panel, Vector3 start, IReadOnlyList<MovementFrame> frames, string colour, double width, double dot)
    {
        var line = new StringBuilder();
        panel.Polyline(line, frames.Select(f => f.Position).Prepend(start));
        svg.Path(line.ToString(), "none", colour, width);
        var dots = new StringBuilder();
        foreach (var f in frames) panel.Dot(dots, f.Position, dot);
        svg.Path(dots.ToString(), colour);
    }

    /// <summary>"stepUp ×1, stepDown ×2, highest +0.20 m": what the transitions did, in order of first occurrence, and the highest the mover rose.</summary>
    private static string Events(IReadOnlyList<MovementFrame> frames, Walk walk)
    {
        var events = frames.SelectMany(f => f.Events).GroupBy(e => e).Select(g => $"{g.Key} ×{I(g.Count())}").ToArray();
        var highest = frames.Count == 0 ? 0f : frames.Max(f => f.Position.Z) - walk.Start.Z;
        return (events.Length == 0 ? "none" : string.Join(", ", events)) + $", highest {(highest >= 0 ? "+" : "")}{F(highest, 2)} m";
    }

    private static string Did(MovementOutcome o) =>
        $"{o.Class}{(o.CrossedGate ? ", crossed the gate" : ", did not cross the gate")}, progress {F(o.Progress, 2)} m, lateral {F(o.Lateral, 2)} m, height {F(o.Dz, 2)} m";
}
