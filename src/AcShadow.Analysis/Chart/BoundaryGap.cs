using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// How far a probe's surface is from a model's geometry: the distance from the probe centre to the nearest
/// surface of any of the shapes (BSP polygons, faces of fitted solids, cylinder or sphere surfaces), minus the probe radius.
/// Negative: the probe reaches that far past the surface. +∞: the model has no shapes. A disagreement near
/// zero on either model's geometry is marginal; a large one is a wrong shape.
/// </summary>
internal static class BoundaryGap
{
    public static float Of(IReadOnlyList<PreparedShape> shapes, Vector3 center, float radius)
    {
        var best = float.PositiveInfinity;
        // Indexed, not foreach: an interface's enumerator is allocated on every call, and this runs per ranked probe.
        for (var i = 0; i < shapes.Count; i++) best = MathF.Min(best, Distance(shapes[i], center, float.PositiveInfinity, float.NegativeInfinity));
        return best - radius;
    }

    /// <summary>
    /// <see cref="Of"/> when the gap may be no wider than <paramref name="limit"/> either way (then
    /// <c>Known</c>, the same bits); otherwise <c>Known</c> is false and the gap is certainly wider than
    /// <paramref name="limit"/>: found without measuring BSP polygons and solid faces that cannot be that
    /// near, and stopping at the first surface that is already nearer than radius − limit.
    /// </summary>
    public static (float Gap, bool Known) Within(IReadOnlyList<PreparedShape> shapes, Vector3 center, float radius, float limit)
    {
        // Both ends widened by far more than float rounding, so "not known" really is wider than the limit.
        var reach = (float)((radius + (double)limit) * (1 + 1e-5) + 1e-6);
        var enough = (float)((radius - (double)limit) * (1 - 1e-5) - 1e-6);
        if (!float.IsFinite(reach) || !float.IsFinite(enough)) return (Of(shapes, center, radius), true);
        var best = float.PositiveInfinity;
        for (var i = 0; i < shapes.Count; i++)
        {
            best = MathF.Min(best, Distance(shapes[i], center, reach, enough));
            if (best < enough) return (best - radius, false);
        }
        return (best - radius, !(best > reach));
    }

    private static float Distance(PreparedShape shape, Vector3 point, float reach, float enough)
    {
        if (shape.Polytope is { } solid)
        {
            var (inPart, _) = shape.Pose.ToLocal(point, 0f);
            return SurfaceDistance.ToNearestFace(solid, inPart, LocalReach(reach, shape.Pose.Scale), LocalEnough(enough, shape.Pose.Scale)) * shape.Pose.Scale;
        }
        var s = shape.Shape;
        switch (s.CollisionType)
        {
            case CollisionType.Bsp when shape.Bsp is { } bsp:
                var (local, _) = shape.Pose.ToLocal(point, 0f);
                return SurfaceDistance.ToNearestPolygon(bsp, local, LocalReach(reach, shape.Pose.Scale), LocalEnough(enough, shape.Pose.Scale)) * shape.Pose.Scale;
            case CollisionType.Cylinder:
                return SurfaceDistance.ToCylinder(s.LocalPosition, s.Radius, s.CylHeight, point);
            case CollisionType.Sphere:
                return SurfaceDistance.ToSphere(s.LocalPosition, s.Radius, point);
            default:
                return float.PositiveInfinity;
        }
    }

    /// <summary>A reach in entity metres as part-frame metres, widened past rounding; +∞ (measure in full) when the scale is not usable.</summary>
    private static float LocalReach(float reach, float scale) =>
        float.IsPositiveInfinity(reach) || !(scale > 0f) ? float.PositiveInfinity : (float)(reach / (double)scale * (1 + 1e-5) + 1e-6);

    /// <summary>A floor in entity metres as part-frame metres, lowered past rounding; −∞ (no early stop) when the scale is not usable.</summary>
    private static float LocalEnough(float enough, float scale) =>
        float.IsNegativeInfinity(enough) || !(scale > 0f) ? float.NegativeInfinity : (float)(enough / (double)scale * (1 - 1e-5) - 1e-6);
}
