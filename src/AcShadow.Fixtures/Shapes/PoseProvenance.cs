namespace AcShadow.Fixtures.Shapes;

/// <summary>
/// Which pose a shadow file's parts are in, and where it came from. <see cref="Source"/> is
/// <see cref="PlacementSource"/> (the placement frame the file's placement block names),
/// <see cref="DefaultAnimationSource"/> or <see cref="MotionTableSource"/>; for the last two the
/// animation and frame number posed, and for a motion table its id, where the id came from, and the
/// style and substate the object is in. <see cref="DoorState"/> is set for doors ("closed" or "open");
/// <see cref="Ethereal"/> says retail makes the object ethereal (no collision) in that state, so the
/// shapes are there to test, not to block. <see cref="DiffersFromPlacement"/>: some part is more than
/// 1 mm or 0.1° away from where the placement frame puts it.
/// </summary>
public sealed record PoseProvenance(
    string Policy,
    string Source,
    uint? MotionTableId,
    string? MotionTableFrom,
    uint? Style,
    uint? Substate,
    uint? AnimationId,
    int? Frame,
    string? DoorState,
    bool Ethereal,
    bool DiffersFromPlacement)
{
    public const string PlacementSource = "placement";
    public const string DefaultAnimationSource = "default-animation";
    public const string MotionTableSource = "motion-table";

    /// <summary>What a file written before poses were recorded would have said: the placement frame.</summary>
    public static PoseProvenance Placement(string policy) => new(policy, PlacementSource, null, null, null, null, null, null, null, false, false);
}
