using System.Numerics;
using System.Text;
using AcShadow.Analysis.Chart.Movement;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// A square panel showing part of the floor from above (north up), landblock-local metres to pixels at one
/// scale, with what the movement drawings put on it: model outlines, gates clipped to the panel, and strokes and
/// dots gathered into path data.
/// </summary>
internal sealed class FloorPanel
{
    private readonly double _left, _top, _minX, _maxY, _scale;

    public double Width { get; }
    public double Height { get; }

    private readonly double _minY, _maxX;

    /// <summary>A panel of <paramref name="size"/> pixels along its longer side showing the box, its top-left at (<paramref name="left"/>, <paramref name="top"/>).</summary>
    public FloorPanel(double left, double top, double size, double minX, double minY, double maxX, double maxY)
    {
        _left = left;
        _top = top;
        _minX = minX;
        _minY = minY;
        _maxX = maxX;
        _maxY = maxY;
        _scale = size / Math.Max(Math.Max(maxX - minX, maxY - minY), 1e-3);
        Width = (maxX - minX) * _scale;
        Height = (maxY - minY) * _scale;
    }

    public double X(double x) => _left + (x - _minX) * _scale;
    public double Y(double y) => _top + (_maxY - y) * _scale;

    public void Frame(SvgDocument svg) => svg.Rect(_left, _top, Width, Height, "none", DrawingPalette.Axis, 0.8);

    /// <summary>The outline's polygons and circles; more polygons than <paramref name="maxPolygons"/> are left out (the footprint box stands for them).</summary>
    public void Outline(SvgDocument svg, ModelOutline outline, string fill, double opacity, string stroke, int maxPolygons = 600)
    {
        if (outline.Polygons.Count <= maxPolygons)
        {
            var data = new StringBuilder();
            foreach (var polygon in outline.Polygons)
            {
                if (polygon.Count < 2) continue;
                for (var k = 0; k < polygon.Count; k++)
                    data.Append(k == 0 ? 'M' : 'L').Append(N(X(polygon[k].X))).Append(' ').Append(N(Y(polygon[k].Y)));
                data.Append('Z');
            }
            svg.Path(data.ToString(), fill, stroke, 0.6, opacity);
        }
        foreach (var (center, radius) in outline.Circles)
            svg.Circle(X(center.X), Y(center.Y), Math.Max(radius * _scale, 1), fill, stroke, 0.8, fillOpacity: opacity);
    }

    /// <summary>The gate plane's trace on the floor, clipped to the panel, dashed.</summary>
    public void Gate(SvgDocument svg, Plane gate, string stroke)
    {
        var n = new Vector2(gate.Normal.X, gate.Normal.Y);
        var length = n.Length();
        if (!(length > 1e-6f)) return;
        var d = gate.D / length;
        n /= length;
        var point = new Vector2(-d * n.X, -d * n.Y);
        var along = new Vector2(-n.Y, n.X);
        // Liang–Barsky against the panel's box.
        double t0 = double.NegativeInfinity, t1 = double.PositiveInfinity;
        bool Clip(double p, double q)
        {
            if (Math.Abs(p) < 1e-12) return q >= 0;
            var t = q / p;
            if (p < 0) t0 = Math.Max(t0, t); else t1 = Math.Min(t1, t);
            return t0 <= t1;
        }
        if (!(Clip(-along.X, point.X - _minX) && Clip(along.X, _maxX - point.X) && Clip(-along.Y, point.Y - _minY) && Clip(along.Y, _maxY - point.Y))) return;
        svg.Line(X(point.X + t0 * along.X), Y(point.Y + t0 * along.Y), X(point.X + t1 * along.X), Y(point.Y + t1 * along.Y), stroke, 1.2, "6 4");
    }

    /// <summary>Path data for a straight stroke from a to b.</summary>
    public void Segment(StringBuilder data, Vector3 a, Vector3 b) =>
        data.Append('M').Append(N(X(a.X))).Append(' ').Append(N(Y(a.Y))).Append('L').Append(N(X(b.X))).Append(' ').Append(N(Y(b.Y)));

    /// <summary>Path data for a polyline through the points.</summary>
    public void Polyline(StringBuilder data, IEnumerable<Vector3> points)
    {
        var first = true;
        foreach (var p in points)
        {
            data.Append(first ? 'M' : 'L').Append(N(X(p.X))).Append(' ').Append(N(Y(p.Y)));
            first = false;
        }
    }

    /// <summary>Path data for a small square dot of half-size <paramref name="half"/> pixels centred on p.</summary>
    public void Dot(StringBuilder data, Vector3 p, double half) =>
        data.Append('M').Append(N(X(p.X) - half)).Append(' ').Append(N(Y(p.Y) - half))
            .Append('h').Append(N(2 * half)).Append('v').Append(N(2 * half)).Append('h').Append(N(-2 * half)).Append('Z');

    private static string N(double v) => SvgDocument.Number(v);
}
