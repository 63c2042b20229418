using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Chart;

/// <summary>
/// How far a probe's surface is from a model's geometry: the distance from the probe centre to the nearest
/// surface of any of the shapes (BSP polygons, cylinder or sphere surfaces), minus the probe radius.
/// Negative: the probe reaches that far past the surface. +∞: the model has no shapes. A disagreement near
/// zero on either model's geometry is marginal; a large one is a wrong shape.
/// </summary>
public static class BoundaryGap
{
    public static float Of(IReadOnlyList<PreparedShape> shapes, Vector3 center, float radius)
    {
        var best = float.PositiveInfinity;
        foreach (var shape in shapes) best = MathF.Min(best, Distance(shape, center));
        return best - radius;
    }

    private static float Distance(PreparedShape shape, Vector3 point)
    {
        var s = shape.Shape;
        switch (s.CollisionType)
        {
            case CollisionType.Bsp when shape.Bsp is { } bsp:
                var (local, _) = shape.Pose.ToLocal(point, 0f);
                return SurfaceDistance.ToNearestPolygon(bsp, local) * shape.Pose.Scale;
            case CollisionType.Cylinder:
                return SurfaceDistance.ToCylinder(s.LocalPosition, s.Radius, s.CylHeight, point);
            case CollisionType.Sphere:
                return SurfaceDistance.ToSphere(s.LocalPosition, s.Radius, point);
            default:
                return float.PositiveInfinity;
        }
    }
}
