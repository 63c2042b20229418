using System.Numerics;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart;

/// <summary>Where a prepared shape is, as an entity-space box: BSP parts by their posed polygon vertices, fitted solids by theirs.</summary>
internal static class ShapeBounds
{
    public static Bounds Of(PreparedShape shape)
    {
        var b = Bounds.Empty;
        if (shape.Polytope is { } solid)
        {
            foreach (var v in solid.Vertices) b = b.Include(shape.Pose.ToEntity(v));
            return b;
        }
        var s = shape.Shape;
        switch (s.CollisionType)
        {
            case CollisionType.Bsp when shape.Bsp is { } bsp:
                foreach (var polygon in bsp.Polygons)
                    foreach (var v in polygon.Vertices) b = b.Include(shape.Pose.ToEntity(v));
                return b;
            case CollisionType.Cylinder:
                return b.Include(s.LocalPosition - new Vector3(s.Radius, s.Radius, 0))
                        .Include(s.LocalPosition + new Vector3(s.Radius, s.Radius, s.CylHeight));
            case CollisionType.Sphere:
                return b.Include(s.LocalPosition - new Vector3(s.Radius)).Include(s.LocalPosition + new Vector3(s.Radius));
            default:
                return b;
        }
    }

    public static Bounds Of(IEnumerable<PreparedShape> shapes) => shapes.Aggregate(Bounds.Empty, (b, s) => b.Include(Of(s)));
}
