using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Everything a batch's output depends on, as index.json records it so verify can regenerate the same
/// files: the dat(s), the policy, the entity scale, the pose and the selection. <see cref="CellDat"/> is recorded
/// only when a landblock is selected (only then does the output depend on it).
/// </summary>
public sealed record BatchInputs(DatSourceInfo Dat, DatSourceInfo? CellDat, ShapePolicy Policy, float EntityScale, BatchSelection Selection)
{
    /// <summary>`--format`; index.json records it only when it is not the default, so older indexes read as canonical.</summary>
    public OutputFormats Formats { get; init; } = OutputFormats.Canonical;

    /// <summary>`--pose`; an index without it was written before poses existed, when every part took its placement frame.</summary>
    public PosePolicy Pose { get; init; } = PosePolicy.Retail;
    public DoorState DoorState { get; init; } = DoorState.Closed;
    public uint? MotionTable { get; init; }

    /// <summary>`--movement`: movement suites the batch adds (null: none; index.json records it only when set).</summary>
    public MovementSelection? Movement { get; init; }

    /// <summary>The build options these inputs stand for.</summary>
    public ShapeBuildOptions BuildOptions() =>
        new(Policy, EntityScale) { Pose = Pose, DoorState = DoorState, MotionTable = MotionTable };
}
