using System.Collections.Immutable;
using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A box tree over a part's polygons, so the nearest polygon to a point is found without measuring every
/// polygon. It returns exactly what measuring every polygon and keeping the minimum returns: a box is
/// skipped only when its distance, less a margin far wider than float rounding, is still beyond the best
/// distance found so far, and the minimum of the rest does not depend on the order it is taken in.
/// Polygons whose vertices are not all finite are measured every time (a NaN there makes the answer NaN,
/// as the plain minimum does).
/// </summary>
internal sealed class NearestPolygonIndex
{
    private const int LeafSize = 4;

    private readonly ImmutableArray<CompiledPolygon> _polygons;
    private readonly int[] _order;
    private readonly int[] _unbounded;
    private readonly Node[] _nodes;
    // Per polygon: how far its vertices stray from its plane, and max(1, |normal|), for the plane bound below.
    private readonly double[] _offPlane;
    private readonly double[] _normalScale;
    // Per node: the largest coordinate magnitude of its box, for the rounding margin in Beyond.
    private readonly double[] _nodeMagnitude;

    private readonly record struct Node(Vector3 Min, Vector3 Max, int Left, int Right, int Start, int Count)
    {
        public bool IsLeaf => Left < 0;
    }

    private NearestPolygonIndex(ImmutableArray<CompiledPolygon> polygons, int[] order, int[] unbounded, Node[] nodes)
    {
        _polygons = polygons;
        _order = order;
        _unbounded = unbounded;
        _nodes = nodes;
        _nodeMagnitude = Array.ConvertAll(nodes, n => Math.Max(MaxAbs(n.Min), MaxAbs(n.Max)));
        _offPlane = new double[polygons.Length];
        _normalScale = new double[polygons.Length];
        for (var i = 0; i < polygons.Length; i++)
        {
            var polygon = polygons[i];
            var off = 0d;
            foreach (var v in polygon.Vertices) off = Math.Max(off, Math.Abs(PlaneValue(polygon, v)));
            _offPlane[i] = off;
            _normalScale[i] = Math.Max(1d, Math.Sqrt((double)polygon.Normal.X * polygon.Normal.X + (double)polygon.Normal.Y * polygon.Normal.Y + (double)polygon.Normal.Z * polygon.Normal.Z));
        }
    }

    public static NearestPolygonIndex Build(ImmutableArray<CompiledPolygon> polygons)
    {
        var mins = new Vector3[polygons.Length];
        var maxs = new Vector3[polygons.Length];
        var bounded = new List<int>(polygons.Length);
        var unbounded = new List<int>();
        for (var i = 0; i < polygons.Length; i++)
        {
            var vertices = polygons[i].Vertices;
            var finite = vertices.Length > 0;
            Vector3 min = new(float.PositiveInfinity), max = new(float.NegativeInfinity);
            foreach (var v in vertices)
            {
                finite &= float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
                min = Vector3.Min(min, v);
                max = Vector3.Max(max, v);
            }
            mins[i] = min;
            maxs[i] = max;
            (finite ? bounded : unbounded).Add(i);
        }
        var order = bounded.ToArray();
        var nodes = new List<Node>();
        if (order.Length > 0) Split(order, 0, order.Length, mins, maxs, nodes);
        return new NearestPolygonIndex(polygons, order, [.. unbounded], [.. nodes]);
    }

    private static int Split(int[] order, int start, int count, Vector3[] mins, Vector3[] maxs, List<Node> nodes)
    {
        Vector3 min = new(float.PositiveInfinity), max = new(float.NegativeInfinity);
        for (var i = start; i < start + count; i++)
        {
            min = Vector3.Min(min, mins[order[i]]);
            max = Vector3.Max(max, maxs[order[i]]);
        }
        var at = nodes.Count;
        nodes.Add(new Node(min, max, -1, -1, start, count));
        if (count <= LeafSize) return at;
        // Halve along the box's longest axis by box centre; ties broken by polygon index so the tree is the same every run.
        var size = max - min;
        var axis = size.X >= size.Y && size.X >= size.Z ? 0 : size.Y >= size.Z ? 1 : 2;
        Array.Sort(order, start, count, Comparer<int>.Create((a, b) =>
        {
            var ca = Axis(mins[a] + maxs[a], axis);
            var cb = Axis(mins[b] + maxs[b], axis);
            var c = ca.CompareTo(cb);
            return c != 0 ? c : a.CompareTo(b);
        }));
        var half = count / 2;
        var left = Split(order, start, half, mins, maxs, nodes);
        var right = Split(order, start + half, count - half, mins, maxs, nodes);
        nodes[at] = nodes[at] with { Left = left, Right = right };
        return at;
    }

    private static float Axis(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;

    /// <summary>
    /// The smallest <see cref="SurfaceDistance.ToPolygon"/> over the part's polygons (+∞ when it has none)
    /// when that is at most <paramref name="within"/> and not below <paramref name="enough"/>; otherwise some
    /// distance greater than <paramref name="within"/>, or the first found below <paramref name="enough"/>.
    /// </summary>
    public float Nearest(Vector3 point, float within = float.PositiveInfinity, float enough = float.NegativeInfinity)
    {
        var best = float.PositiveInfinity;
        foreach (var i in _unbounded) best = MathF.Min(best, SurfaceDistance.ToPolygon(_polygons[i], point));
        if (float.IsNaN(best) || best < enough || _nodes.Length == 0) return best;
        // Depth-first, at most one pending sibling per level: the tree is a halving, so 64 levels is more than any part has.
        // Each pending node keeps its box distance, worked out once when it was pushed.
        Span<int> stack = stackalloc int[64];
        Span<double> distances = stackalloc double[64];
        var pointMagnitude = MaxAbs(point);
        var top = 0;
        stack[top] = 0;
        distances[top++] = BoxDistance(_nodes[0], point);
        while (top > 0)
        {
            var at = stack[--top];
            var node = _nodes[at];
            if (Beyond(distances[top], Math.Max(pointMagnitude, _nodeMagnitude[at]), MathF.Min(best, within))) continue;
            if (node.IsLeaf)
            {
                for (var k = node.Start; k < node.Start + node.Count; k++)
                {
                    var index = _order[k];
                    var polygon = _polygons[index];
                    // A polygon is never nearer than its plane (less how far its vertices stray from it): one dot product rules most out.
                    if (PlaneBeyond(index, point, pointMagnitude, MathF.Min(best, within))) continue;
                    best = MathF.Min(best, SurfaceDistance.ToPolygon(polygon, point));
                    if (best < enough) return best;
                }
                if (float.IsNaN(best)) return best;
                continue;
            }
            // Nearer child last, so it is taken first and tightens the bound for the other.
            var toLeft = BoxDistance(_nodes[node.Left], point);
            var toRight = BoxDistance(_nodes[node.Right], point);
            var leftFirst = toLeft <= toRight;
            stack[top] = leftFirst ? node.Right : node.Left;
            distances[top++] = leftFirst ? toRight : toLeft;
            stack[top] = leftFirst ? node.Left : node.Right;
            distances[top++] = leftFirst ? toLeft : toRight;
        }
        return best;
    }

    /// <summary>
    /// True when nothing in the box can come nearer than <paramref name="best"/>. Worked in double so huge
    /// coordinates do not overflow, with a margin of 1e-5 of the magnitudes involved plus 1e-6 m: a polygon's
    /// float distance is off by a few parts in 1e7 of those magnitudes at most.
    /// </summary>
    private static bool Beyond(double boxDistance, double magnitude, float best) =>
        float.IsFinite(best) && boxDistance - (1e-5 * magnitude + 1e-6) > best;

    /// <summary>
    /// Every point x of the polygon's edges and inside has |n·x + d| at most the vertices' offset (the plane
    /// value is linear), so |n·p + d| − offset over max(1, |n|) bounds both the distance to the polygon and
    /// the |n·p + d| <see cref="SurfaceDistance.ToPolygon"/> returns for a point over its inside.
    /// </summary>
    private bool PlaneBeyond(int index, Vector3 point, double pointMagnitude, float best)
    {
        if (!float.IsFinite(best)) return false;
        var polygon = _polygons[index];
        var bound = (Math.Abs(PlaneValue(polygon, point)) - _offPlane[index]) / _normalScale[index];
        var magnitude = Math.Max(pointMagnitude, Math.Abs((double)polygon.D)) * _normalScale[index] + _offPlane[index];
        return bound - (1e-5 * magnitude + 1e-6) > best;
    }

    private static double PlaneValue(CompiledPolygon polygon, Vector3 p) =>
        (double)polygon.Normal.X * p.X + (double)polygon.Normal.Y * p.Y + (double)polygon.Normal.Z * p.Z + polygon.D;

    private static double BoxDistance(in Node node, Vector3 p)
    {
        var dx = Outside(p.X, node.Min.X, node.Max.X);
        var dy = Outside(p.Y, node.Min.Y, node.Max.Y);
        var dz = Outside(p.Z, node.Min.Z, node.Max.Z);
        return Math.Sqrt(dx * dx + dy * dy + dz * dz);
    }

    private static double Outside(float v, float min, float max) => v < min ? (double)min - v : v > max ? (double)v - max : 0d;

    private static double MaxAbs(Vector3 v) => Math.Max(Math.Abs((double)v.X), Math.Max(Math.Abs((double)v.Y), Math.Abs((double)v.Z)));
}
