using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// How far a point is from geometry, in metres: the measure "how close to the boundary" a probe is. Not a
/// retail function; used to rank disagreements and to keep float noise out of invariance tests.
/// </summary>
internal static class SurfaceDistance
{
    /// <summary>
    /// Distance from a point to a polygon: to its plane when the point's projection falls inside every
    /// edge, else to the nearest edge segment (exact for convex planar polygons).
    /// </summary>
    public static float ToPolygon(CompiledPolygon polygon, Vector3 point)
    {
        var dist = polygon.Distance(point);
        var n = polygon.Normal;
        var foot = new Vector3(point.X - n.X * dist, point.Y - n.Y * dist, point.Z - n.Z * dist);
        var inside = true;
        var edges = polygon.Edges;
        for (var i = 0; i < edges.Length && inside; i++)
            inside = PolygonPlane.Dot(Vec.Sub(foot, edges[i].Start), edges[i].Inward) >= 0f;
        if (inside) return MathF.Abs(dist);
        var best = float.PositiveInfinity;
        foreach (var edge in edges)
            best = MathF.Min(best, ToSegment(edge.Start, edge.Vector, edge.LengthSquared, point));
        return best;
    }

    private static float ToSegment(Vector3 start, Vector3 edge, float lengthSquared, Vector3 point)
    {
        var disp = Vec.Sub(point, start);
        var t = lengthSquared > 0f ? Math.Clamp(PolygonPlane.Dot(disp, edge) / lengthSquared, 0f, 1f) : 0f;
        var closest = new Vector3(start.X + edge.X * t, start.Y + edge.Y * t, start.Z + edge.Z * t);
        return MathF.Sqrt(Vec.DistanceSquared(point, closest));
    }

    /// <summary>Distance from a point to the nearest polygon of a part (part space); +∞ for a part with none.</summary>
    public static float ToNearestPolygon(CompiledBsp bsp, Vector3 point) => bsp.Nearest.Nearest(point);

    /// <summary>
    /// <see cref="ToNearestPolygon(CompiledBsp, Vector3)"/> when it lies between <paramref name="enough"/> and
    /// <paramref name="within"/> (the same bits); otherwise only some distance beyond that range on the same
    /// side, found without measuring what cannot change the verdict.
    /// </summary>
    internal static float ToNearestPolygon(CompiledBsp bsp, Vector3 point, float within, float enough) => bsp.Nearest.Nearest(point, within, enough);

    /// <summary>The minimum of <see cref="ToPolygon"/> over a convex solid's faces (point in its frame), bounded as above.</summary>
    internal static float ToNearestFace(ConvexPolytope solid, Vector3 point, float within, float enough) => solid.Nearest.Nearest(point, within, enough);

    /// <summary>Distance from a point to the surface of a vertical cylinder (0 inside measured as depth, negative).</summary>
    public static float ToCylinder(Vector3 baseCenter, float radius, float height, Vector3 point)
    {
        float dx = point.X - baseCenter.X, dy = point.Y - baseCenter.Y;
        var radial = MathF.Sqrt(dx * dx + dy * dy) - radius;
        var vertical = MathF.Max(baseCenter.Z - point.Z, point.Z - (baseCenter.Z + height));
        if (radial <= 0f && vertical <= 0f) return MathF.Max(radial, vertical);
        var r = MathF.Max(radial, 0f);
        var v = MathF.Max(vertical, 0f);
        return MathF.Sqrt(r * r + v * v);
    }

    /// <summary>Signed distance from a point to a sphere's surface (negative inside).</summary>
    public static float ToSphere(Vector3 center, float radius, Vector3 point) => MathF.Sqrt(Vec.DistanceSquared(point, center)) - radius;
}
