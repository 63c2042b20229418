using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// How a Setup's parts are posed: by <see cref="MotionFrames"/> when an animation poses them (an animation
/// frame's part frames, one for every part at least: a part the animation has no frame for gets the frame
/// retail leaves it at, origin 0 and no rotation), else by <see cref="Placement"/>. The placement frame is
/// always chosen: the motion pose is measured against it.
/// </summary>
public sealed record ResolvedPose(PlacementFrame? Placement, IReadOnlyList<Frame>? MotionFrames, PoseProvenance Provenance);
