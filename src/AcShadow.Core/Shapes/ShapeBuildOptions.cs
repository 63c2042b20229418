using AcShadow.Core.Poses;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Shapes;

/// <summary>
/// How to build: the policy, the entity scale (the object's own scale, 1 for most), the pose the parts
/// take (<see cref="Pose"/>), a door's state (closed unless set; only doors read it) and a motion table to pose by
/// instead of the door catalog's (null: the catalog's, then the Setup's own).
/// </summary>
public sealed record ShapeBuildOptions(ShapePolicy Policy, float EntityScale = 1f)
{
    public PosePolicy Pose { get; init; } = PosePolicy.Retail;
    public DoorState DoorState { get; init; } = DoorState.Closed;
    public uint? MotionTable { get; init; }

    /// <summary>The options the pose is resolved under.</summary>
    public PoseSettings PoseSettings => new(Policy, Pose, DoorState, MotionTable);
}
