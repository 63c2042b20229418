using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A shape the object query tests: where it came from, a readable name ("part 0 (GfxObj 0x010044B5)",
/// "CylSphere 1", "Sphere 0"), its pose in entity space and, for a BSP shape, its compiled tree. A part
/// modelled by a fitted solid instead carries it, in part space: <see cref="Box"/> (its faces also in
/// <see cref="Polytope"/>) or <see cref="Polytope"/> alone (a convex hull).
/// </summary>
internal sealed record PreparedShape(ShadowShape Shape, string Name, PartPose Pose, CompiledBsp? Bsp)
{
    public OrientedBox? Box { get; init; }
    public ConvexPolytope? Polytope { get; init; }

    public static string NameOf(ShadowShape s) => s.Source switch
    {
        _ when s.SourceIndex < 0 => "Setup Radius x Height",
        ShapeSource.Part => $"part {s.SourceIndex} (GfxObj 0x{s.GfxObjId ?? 0:X8})",
        ShapeSource.CylSphere => $"CylSphere {s.SourceIndex}",
        _ => $"Sphere {s.SourceIndex}",
    };
}
