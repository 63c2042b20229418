using System.Numerics;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Fixtures.Geometry;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.View;

/// <summary>
/// A <see cref="ViewScene"/> drawn as three orthographic views (top, front, side; <see cref="ThreeViewLayout"/>)
/// at one scale, with a scale bar, a legend of the groups (their colours) and numbered labels. Filled groups
/// (<see cref="ViewGroup.Filled"/>: the reference model, or each chosen model of a compiled scene) are drawn
/// filled; other models are outlines, dashed for union; chart failures are dots.
/// Hand-written SVG, two decimals, no timestamps: the same scene gives the same bytes.
/// </summary>
public static class ThreeViewSvg
{
    private const int MaxKeyLines = 40;

    public static ThreeViewLayout Layout(ViewScene view) => ThreeViewLayout.Fit(
        Bounds(view).Min, Bounds(view).Max, Math.Min(Keys(view).Count, MaxKeyLines) + 1 + view.Notes.Count);

    public static string Write(ViewScene view)
    {
        var layout = Layout(view);
        var svg = new SvgDocument(layout.Width, layout.Height);
        svg.Text(20, 28, view.Title, 17, "start", "bold");
        svg.Text(20, 48, "Top, front and side views in metres, one scale for all three; axes as in the dat (x east, y north, z up). Numbers name what is listed below.", 12);
        Legend(svg, view, 20, 70);

        Panel(svg, layout.TopCorner, layout.SpanX, layout.SpanY, "top: from above (x →, y ↑)");
        Panel(svg, layout.FrontCorner, layout.SpanX, layout.SpanZ, "front: from −y, looking north (x →, z ↑)");
        Panel(svg, layout.SideCorner, layout.SpanY, layout.SpanZ, "side: from +x, looking west (y →, z ↑)");
        foreach (var group in view.Groups)
            foreach (var o in group.Objects)
                foreach (var shape in o.Shapes)
                {
                    Draw(svg, layout.Top, group, o.Frame, shape.Outline);
                    Draw(svg, layout.Front, group, o.Frame, shape.Outline);
                    Draw(svg, layout.Side, group, o.Frame, shape.Outline);
                }

        var keys = Keys(view);
        // A single object's shapes are told apart from the front; a landblock's objects from above.
        Func<Vector3, (double X, double Y)> keyView = KeysAreShapes(view) ? layout.Front : layout.Top;
        for (var k = 0; k < keys.Count; k++)
        {
            var (at, _) = keys[k];
            var (x, y) = keyView(at);
            svg.Circle(x, y, 8, "#ffffff", "#222222", 0.8);
            svg.Text(x, y + 4, I(k + 1), 10, "middle", "bold");
        }
        var bottom = layout.FrontCorner.Y + layout.SpanZ;
        ScaleBar(svg, layout, layout.FrontCorner.X, bottom + 34);
        var line = bottom + 72;
        foreach (var (k, (_, label)) in keys.Take(MaxKeyLines).Select((key, i) => (i, key)))
        {
            svg.Text(20, line, $"{I(k + 1)}  {label}", 11.5);
            line += 16;
        }
        if (keys.Count > MaxKeyLines) { svg.Text(20, line, $"… and {I(keys.Count - MaxKeyLines)} more (see the glb's node names)", 11.5); line += 16; }
        foreach (var note in view.Notes) { svg.Text(20, line, note, 11.5, fill: "#555555"); line += 16; }
        return svg.Render();
    }

    /// <summary>
    /// What the numbers name: the filled group's shapes of a single object, or the placed objects of a
    /// landblock, each with its group's name when several groups are filled (a compiled scene's chosen models).
    /// </summary>
    private static IReadOnlyList<(Vector3 At, string Label)> Keys(ViewScene view)
    {
        var keyed = KeyedGroups(view);
        if (KeysAreShapes(view))
            return keyed[0].Objects[0].Shapes.Select(s => (keyed[0].Objects[0].Frame.Apply(s.Anchor), $"{s.Name} ({keyed[0].Name})")).ToArray();
        return keyed.SelectMany(g => g.Objects.Select(o => (o.Frame.Position, keyed.Count == 1 ? o.Name : $"{o.Name} ({g.Name})"))).ToArray();
    }

    private static IReadOnlyList<ViewGroup> KeyedGroups(ViewScene view) =>
        view.Groups.Any(g => g.Filled) ? view.Groups.Where(g => g.Filled).ToArray() : view.Groups.Take(1).ToArray();

    private static bool KeysAreShapes(ViewScene view) => KeyedGroups(view) is [{ Objects.Count: 1 }];

    private static void Legend(SvgDocument svg, ViewScene view, double x, double y)
    {
        foreach (var group in view.Groups)
        {
            var label = $"{group.Name} ({I(group.ShapeCount)} shape{(group.ShapeCount == 1 ? "" : "s")})";
            if (group.Objects.All(o => o.Shapes.All(s => s.Outline is PointsOutline)))
                svg.Circle(x + 6, y - 4, 4, group.Colour, "#ffffff", 0.5);
            else
                svg.Rect(x, y - 10, 12, 12, group.Filled ? group.Colour : "none", group.Colour, 1.5, fillOpacity: group.Filled ? 0.35 : 1, dash: Dash(group));
            svg.Text(x + 17, y, label, 12);
            x += 34 + label.Length * 6.6;
        }
    }

    private static void Panel(SvgDocument svg, (double X, double Y) corner, double w, double h, string title)
    {
        svg.Rect(corner.X, corner.Y, w, h, "#fbfbfb", "#bbbbbb", 0.8);
        svg.Text(corner.X, corner.Y - 8, title, 12, weight: "bold");
    }

    private static void ScaleBar(SvgDocument svg, ThreeViewLayout layout, double x, double y)
    {
        var metres = NiceLength(Math.Max(layout.SpanX, 200) * 0.3 / layout.Scale);
        var length = metres * layout.Scale;
        svg.Line(x, y, x + length, y, "#222222", 2);
        svg.Line(x, y - 5, x, y + 5, "#222222", 1.5);
        svg.Line(x + length, y - 5, x + length, y + 5, "#222222", 1.5);
        svg.Text(x + length + 8, y + 4, $"{F(metres, metres < 1 ? 2 : 0)} m (scale bar, all views)", 11.5);
    }

    private static void Draw(SvgDocument svg, Func<Vector3, (double X, double Y)> project, ViewGroup group, Frame frame, ShapeOutline outline)
    {
        var fill = group.Filled ? group.Colour : "none";
        var dash = Dash(group);
        switch (outline)
        {
            case PolygonOutline polygons:
                foreach (var polygon in polygons.Polygons)
                    svg.Polygon(polygon.Select(v => project(frame.Apply(v))), fill, 0.22, group.Colour, 0.9, dash);
                break;
            case CylinderOutline c:
            {
                var b = frame.Apply(c.Base);
                var (bx, by) = project(b);
                var (_, uy) = project(b with { Z = b.Z + c.Height });
                var r = Math.Max(Math.Abs(project(b + new Vector3(c.Radius, 0, 0)).X - bx), Math.Abs(project(b + new Vector3(0, c.Radius, 0)).X - bx));
                // Cylinders stand upright: seen from above a circle, from the side a rectangle.
                if (Math.Abs(by - uy) < 1e-9 && project(b with { Z = b.Z + 1 }).Y == by)
                    svg.Circle(bx, by, r, group.Colour, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                else
                    svg.Rect(bx - r, Math.Min(by, uy), 2 * r, Math.Abs(by - uy), group.Colour, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                break;
            }
            case SphereOutline s:
            {
                var (cx, cy) = project(frame.Apply(s.Center));
                svg.Circle(cx, cy, Math.Abs(project(frame.Apply(s.Center) + new Vector3(0, 0, s.Radius)).Y - cy), group.Colour, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                break;
            }
            case PointsOutline points:
                foreach (var p in points.Points)
                {
                    var (px, py) = project(frame.Apply(p));
                    svg.Circle(px, py, 3.2, group.Colour, "#ffffff", 0.6);
                }
                break;
        }
    }

    private static string? Dash(ViewGroup group) => group.Name == ViewModels.Union ? "5 3" : null;

    /// <summary>The box holding every shape of every group in the view's frame (a unit box round the origin when empty).</summary>
    public static (Vector3 Min, Vector3 Max) Bounds(ViewScene view)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        void Add(Vector3 p) { min = Vector3.Min(min, p); max = Vector3.Max(max, p); }
        foreach (var group in view.Groups)
            foreach (var o in group.Objects)
                foreach (var shape in o.Shapes)
                    switch (shape.Outline)
                    {
                        case PolygonOutline p: foreach (var v in p.Polygons.SelectMany(v => v)) Add(o.Frame.Apply(v)); break;
                        case CylinderOutline c:
                            var b = o.Frame.Apply(c.Base);
                            Add(b - new Vector3(c.Radius, c.Radius, 0)); Add(b + new Vector3(c.Radius, c.Radius, c.Height));
                            break;
                        case SphereOutline s:
                            var centre = o.Frame.Apply(s.Center);
                            Add(centre - new Vector3(s.Radius)); Add(centre + new Vector3(s.Radius));
                            break;
                        case PointsOutline pts: foreach (var v in pts.Points) Add(o.Frame.Apply(v)); break;
                    }
        return min.X > max.X ? (new Vector3(-0.5f), new Vector3(0.5f)) : (min, max);
    }

    private static double NiceLength(double raw)
    {
        var magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        var f = raw / magnitude;
        return (f < 2 ? 1 : f < 5 ? 2 : 5) * magnitude;
    }
}
