using System.Numerics;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Fixtures.Geometry;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.View;

/// <summary>
/// A <see cref="ViewScene"/> drawn as three orthographic views (top, front, side; <see cref="ThreeViewLayout"/>)
/// at one scale, with a scale bar, a legend of the layers, numbered labels and the scene's notes and
/// warnings. The layout is computed from the text (measured, <see cref="TextMeasure"/>) as well as the
/// geometry: lines wrap to the canvas, the legend wraps into rows, panels are as wide as their titles, and
/// the canvas grows to hold whatever is drawn. Filled layers (<see cref="ViewGroup.Filled"/>, the reference)
/// are drawn first and filled; every other layer is an outline over them (dashed for union); chart failures
/// are markers, diamonds for false passes and squares for false blocks, in their model's colour. Each layer
/// is one <c>&lt;g&gt;</c> with an id and a title, so a viewer can hide it.
/// Hand-written SVG, two decimals, no timestamps: the same scene gives the same bytes.
/// </summary>
public static class ThreeViewSvg
{
    private const int MaxKeyLines = 40;
    private const double TitleSize = 17, TextSize = 12, FootSize = 11.5, Line = 16, KeySize = 9.5;
    private const string TopTitle = "top: from above (x →, y ↑)";
    private const string FrontTitle = "front: from −y, looking north (x →, z ↑)";
    private const string SideTitle = "side: from +x, looking west (y →, z ↑)";
    private const string Subtitle = "Top, front and side views in metres, one scale for all three; axes as in the dat (x east, y north, z up). Numbers name what is listed below.";

    public static ThreeViewLayout Layout(ViewScene view)
    {
        var (min, max) = Bounds(view);
        var titles = (Title(TopTitle), Title(FrontTitle), Title(SideTitle));
        var width = ThreeViewLayout.Fit(min, max, 0, titles).Width;
        return ThreeViewLayout.Fit(min, max, Header(view, width, null), titles);
    }

    public static string Write(ViewScene view)
    {
        var layout = Layout(view);
        var svg = new SvgDocument(layout.Width, layout.Bottom);
        Header(view, layout.Width, svg);

        Panel(svg, layout.TopCorner, layout.SpanX, layout.SpanY, TopTitle);
        Panel(svg, layout.FrontCorner, layout.SpanX, layout.SpanZ, FrontTitle);
        Panel(svg, layout.SideCorner, layout.SpanY, layout.SpanZ, SideTitle);
        for (var g = 0; g < view.Groups.Count; g++)
        {
            var group = view.Groups[g];
            svg.BeginGroup("layer-" + Slug(group.Name), $"{group.Title}: {group.Description}");
            foreach (var o in group.Objects)
                foreach (var shape in o.Shapes)
                {
                    Draw(svg, layout.Top, group, o.Frame, shape.Outline);
                    Draw(svg, layout.Front, group, o.Frame, shape.Outline);
                    Draw(svg, layout.Side, group, o.Frame, shape.Outline);
                }
            svg.EndGroup();
        }

        var keys = Keys(view);
        // A single object's shapes are told apart from the front; a landblock's objects from above.
        var front = KeysAreShapes(view);
        Func<Vector3, (double X, double Y)> keyView = front ? layout.Front : layout.Top;
        var (corner, w, h) = front ? (layout.FrontCorner, layout.SpanX, layout.SpanZ) : (layout.TopCorner, layout.SpanX, layout.SpanY);
        Labels(svg, keys.Select(k => (keyView(k.At), k.Key)).ToArray(), corner, w, h);

        var y = layout.Bottom + 34;
        ScaleBar(svg, layout, layout.FrontCorner.X, y);
        y += 38;
        var wrap = layout.Width - 2 * ThreeViewLayout.Margin;
        foreach (var (key, label) in keys.Take(MaxKeyLines).Select(k => (k.Key, k.Label)))
            y = Paragraph(svg, y, $"{key}  {label}", FootSize, wrap, DrawingPalette.Ink);
        if (keys.Count > MaxKeyLines) y = Paragraph(svg, y, $"… and {I(keys.Count - MaxKeyLines)} more (see the glb's node names)", FootSize, wrap, DrawingPalette.Ink);
        foreach (var note in view.Notes) y = Paragraph(svg, y, note, FootSize, wrap, DrawingPalette.Note);
        foreach (var warning in view.Warnings) y = Paragraph(svg, y, "warning: " + warning, FootSize, wrap, DrawingPalette.Warning);
        return svg.Render();
    }

    /// <summary>The title, the subtitle and the legend from the top of the canvas; drawn when <paramref name="svg"/> is given. Returns where the panels may start.</summary>
    private static double Header(ViewScene view, double width, SvgDocument? svg)
    {
        var wrap = width - 2 * ThreeViewLayout.Margin;
        var y = 28.0;
        foreach (var line in Wrap(view.Title, TitleSize, true, wrap))
        {
            svg?.Text(ThreeViewLayout.Margin, y, line, TitleSize, "start", "bold");
            y += 22;
        }
        foreach (var line in Wrap(Subtitle, TextSize, false, wrap))
        {
            svg?.Text(ThreeViewLayout.Margin, y - 2, line, TextSize);
            y += Line;
        }
        return Legend(svg, view, ThreeViewLayout.Margin, y + 8, width - ThreeViewLayout.Margin) + 4;
    }

    /// <summary>One entry per layer (swatch, title, shape count), wrapped into rows within <paramref name="right"/>; returns the bottom of the last row.</summary>
    private static double Legend(SvgDocument? svg, ViewScene view, double left, double y, double right)
    {
        var x = left;
        foreach (var group in view.Groups)
        {
            var label = group.FalsePass is null
                ? $"{group.Title}: {I(group.ShapeCount)} shape{(group.ShapeCount == 1 ? "" : "s")}"
                : group.Title;
            var lines = Wrap(label, TextSize, false, right - left - 17);
            var width = 17 + lines.Max(l => TextMeasure.Width(l, TextSize)) + 18;
            if (x > left && x + width > right)
            {
                x = left;
                y += Line + 4;
            }
            if (svg is not null)
            {
                if (group.FalsePass is { } falsePass) Marker(svg, x + 6, y - 4, 5, group.Colour, falsePass);
                else svg.Rect(x, y - 10, 12, 12, group.Filled ? group.Colour : "none", group.Colour, 1.5, fillOpacity: group.Filled ? 0.35 : 1, dash: Dash(group));
                for (var l = 0; l < lines.Count; l++) svg.Text(x + 17, y + l * Line, lines[l], TextSize);
            }
            if (lines.Count > 1)
            {
                y += lines.Count * Line + 4;
                x = left;
            }
            else x += width;
        }
        return x > left ? y + Line : y;
    }

    private static void Panel(SvgDocument svg, (double X, double Y) corner, double w, double h, string title)
    {
        svg.Rect(corner.X, corner.Y, w, h, DrawingPalette.Panel, DrawingPalette.PanelEdge, 0.8);
        svg.Text(corner.X, corner.Y - 8, title, TextSize, weight: "bold");
    }

    private static double Title(string title) => TextMeasure.Width(title, TextSize, bold: true);

    /// <summary>
    /// Numbered labels beside what they name, never on it: each in a box placed clear of the points and of
    /// the other labels inside the panel where it can be, with a leader line to a dot at its point.
    /// </summary>
    private static void Labels(SvgDocument svg, IReadOnlyList<((double X, double Y) At, string Key)> keys, (double X, double Y) corner, double w, double h)
    {
        var placer = new LabelPlacer(corner.X + 2, corner.Y + 2, corner.X + w - 2, corner.Y + h - 2);
        foreach (var (at, _) in keys) placer.Avoid(at.X, at.Y, 4);
        foreach (var (at, key) in keys)
        {
            var width = TextMeasure.Width(key, KeySize, bold: true) + 6;
            var (tx, ty, anchor) = placer.Place(at.X, at.Y, width, KeySize + 5);
            var left = Math.Max(2, anchor == "start" ? tx : tx - width);
            var top = Math.Max(2, ty - KeySize - 1);
            ty = top + KeySize + 1;
            var nearX = Math.Clamp(at.X, left, left + width);
            var nearY = Math.Clamp(at.Y, top, top + KeySize + 5);
            svg.Line(at.X, at.Y, nearX, nearY, DrawingPalette.Ink, 0.7);
            svg.Circle(at.X, at.Y, 1.6, DrawingPalette.Ink);
            svg.Rect(left, top, width, KeySize + 5, "#ffffff", DrawingPalette.Ink, 0.7);
            svg.Text(left + width / 2, ty + 1, key, KeySize, "middle", "bold");
        }
    }

    /// <summary>A text wrapped to <paramref name="width"/>, from baseline <paramref name="y"/>; returns the next line's baseline.</summary>
    private static double Paragraph(SvgDocument svg, double y, string text, double size, double width, string fill)
    {
        foreach (var line in Wrap(text, size, false, width))
        {
            svg.Text(ThreeViewLayout.Margin, y, line, size, fill: fill);
            y += Line;
        }
        return y;
    }

    /// <summary>Words into lines no wider than <paramref name="width"/> (a word longer than that has a line of its own).</summary>
    internal static IReadOnlyList<string> Wrap(string text, double size, bool bold, double width)
    {
        var lines = new List<string>();
        var line = "";
        foreach (var word in text.Split(' '))
        {
            var candidate = line.Length == 0 ? word : line + " " + word;
            if (line.Length > 0 && TextMeasure.Width(candidate, size, bold) > width)
            {
                lines.Add(line);
                line = "    " + word;
            }
            else line = candidate;
        }
        lines.Add(line);
        return lines;
    }

    /// <summary>
    /// What the numbers name: the reference's shapes of a single object, or every placed object and cell of a
    /// landblock by the key every drawing of it uses (the scene's object index, the cell's "c" number).
    /// </summary>
    private static IReadOnlyList<(Vector3 At, string Key, string Label)> Keys(ViewScene view)
    {
        if (KeysAreShapes(view))
        {
            var g = KeyedGroups(view)[0];
            var o = g.Objects[0];
            return o.Shapes.Select((s, i) => (o.Frame.Apply(s.Anchor), I(i + 1), $"{s.Name} ({g.Name})")).ToArray();
        }
        var seen = new HashSet<string>();
        var keys = new List<(Vector3, string, string)>();
        foreach (var g in view.Groups.Where(g => g.FalsePass is null))
            foreach (var o in g.Objects)
                if (o.Key is { } key && seen.Add(key))
                    keys.Add((o.Frame.Position, key, $"{o.Name} ({g.Name})"));
        return keys.OrderBy(k => k.Item2.StartsWith('c') ? 1 : 0).ThenBy(k => k.Item2.Length).ThenBy(k => k.Item2, StringComparer.Ordinal).ToArray();
    }

    private static IReadOnlyList<ViewGroup> KeyedGroups(ViewScene view) =>
        view.Groups.Any(g => g.Filled) ? view.Groups.Where(g => g.Filled).ToArray() : view.Groups.Where(g => g.FalsePass is null).Take(1).ToArray();

    private static bool KeysAreShapes(ViewScene view) => KeyedGroups(view) is [{ Objects: [{ Key: null }] }];

    private static void ScaleBar(SvgDocument svg, ThreeViewLayout layout, double x, double y)
    {
        var metres = NiceLength(Math.Max(layout.SpanX, 200) * 0.3 / layout.Scale);
        var length = metres * layout.Scale;
        svg.Line(x, y, x + length, y, DrawingPalette.Ink, 2);
        svg.Line(x, y - 5, x, y + 5, DrawingPalette.Ink, 1.5);
        svg.Line(x + length, y - 5, x + length, y + 5, DrawingPalette.Ink, 1.5);
        svg.Text(x + length + 8, y + 4, $"{F(metres, metres < 1 ? 2 : 0)} m (scale bar, all views)", FootSize);
    }

    private static void Draw(SvgDocument svg, Func<Vector3, (double X, double Y)> project, ViewGroup group, Frame frame, ShapeOutline outline)
    {
        // The reference is filled; every other layer is an outline, so the reference shows through it.
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
                var r = Radius(project, b, bx, c.Radius);
                // Cylinders stand upright: seen from above a circle, from the side a rectangle.
                if (Math.Abs(by - uy) < 1e-9 && project(b with { Z = b.Z + 1 }).Y == by)
                    svg.Circle(bx, by, r, fill, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                else
                    svg.Rect(bx - r, Math.Min(by, uy), 2 * r, Math.Abs(by - uy), fill, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                break;
            }
            case SphereOutline s:
            {
                var centre = frame.Apply(s.Center);
                var (cx, cy) = project(centre);
                svg.Circle(cx, cy, Radius(project, centre, cx, s.Radius), fill, group.Colour, 1.2, fillOpacity: 0.35, dash: dash);
                break;
            }
            case PointsOutline points:
                foreach (var p in points.Points)
                {
                    var (px, py) = project(frame.Apply(p));
                    Marker(svg, px, py, 4, group.Colour, points.FalsePass);
                }
                break;
        }
    }

    /// <summary>A radius on the page: every view's horizontal axis is x or y, so the larger of the two offsets is the one it shows.</summary>
    private static double Radius(Func<Vector3, (double X, double Y)> project, Vector3 centre, double cx, float radius) =>
        Math.Max(Math.Abs(project(centre + new Vector3(radius, 0, 0)).X - cx), Math.Abs(project(centre + new Vector3(0, radius, 0)).X - cx));

    /// <summary>A false pass as a filled diamond, a false block as a hollow square, <paramref name="r"/> from centre to corner.</summary>
    private static void Marker(SvgDocument svg, double x, double y, double r, string colour, bool falsePass)
    {
        if (falsePass) svg.Polygon([(x, y - r), (x + r, y), (x, y + r), (x - r, y)], colour, 1, "#ffffff", 0.6);
        else svg.Rect(x - r * 0.75, y - r * 0.75, r * 1.5, r * 1.5, "#ffffff", colour, 1.6);
    }

    private static string? Dash(ViewGroup group) => group.Name == ViewModels.Union ? "5 3" : null;

    private static string Slug(string name) => string.Concat(name.Select(c => char.IsAsciiLetterOrDigit(c) ? c : '-'));

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
