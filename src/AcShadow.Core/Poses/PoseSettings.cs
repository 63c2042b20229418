using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// What a Setup's pose is resolved under: the policy that picks its placement frame, the pose policy, the
/// door state (closed or open; only doors read it), and a motion table chosen over the Setup's own (null: its own).
/// </summary>
public sealed record PoseSettings(ShapePolicy Placement, PosePolicy Pose, DoorState DoorState, uint? MotionTable);
