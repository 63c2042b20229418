using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Poses;

/// <summary>
/// How a Setup's parts are posed: by <see cref="MotionFrames"/> (an animation frame's part frames, which may
/// be fewer than the parts) where there are some, else by <see cref="Placement"/>. The placement frame is
/// always chosen: it poses parts the animation frame does not reach, and the motion pose is measured against it.
/// </summary>
public sealed record ResolvedPose(PlacementFrame? Placement, IReadOnlyList<Frame>? MotionFrames, PoseProvenance Provenance);
