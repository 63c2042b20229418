namespace AcShadow.Fixtures.Movement;

/// <summary>
/// OBJECTINFO: what the mover is this frame. Contact and OnWalkable come from the previous frame's result
/// (validate_transition recomputes them); step heights are the Setup's × scale; StepDown is on (not a missile).
/// </summary>
internal sealed class ObjectInfo
{
    public bool Contact;
    public bool OnWalkable;
    public bool EdgeSlide;
    public float StepUpHeight;
    public float StepDownHeight;

    /// <summary>The velocity was killed (OBJECTINFO::kill_velocity) during this transition.</summary>
    public bool VelocityStopped;

    // OBJECTINFO::is_valid_walkable
    public static bool IsValidWalkable(System.Numerics.Vector3 normal) => normal.Z >= MovementConstants.FloorZ;
}
