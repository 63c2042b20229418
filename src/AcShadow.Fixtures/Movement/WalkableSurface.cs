using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// The walkable polygon a step-down last stood the sphere on (SPHEREPATH set_walkable): the polygon, the part
/// pose it is in, the sphere in part space (walkable_check_pos, whose radius check_walkables halves in place,
/// as retail does: movement.md §5.3 #8) and the part's up axis.
/// </summary>
internal sealed class WalkableSurface(CompiledPolygon polygon, PartPose pose, Vector3 center, float radius, Vector3 up)
{
    public CompiledPolygon Polygon { get; } = polygon;
    public PartPose Pose { get; } = pose;
    public Vector3 Up { get; } = up;
    public Vector3 Center { get; set; } = center;
    public float Radius { get; set; } = radius;
}
