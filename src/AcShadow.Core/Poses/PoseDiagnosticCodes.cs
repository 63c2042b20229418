namespace AcShadow.Core.Poses;

/// <summary>The diagnostic codes of the motion pose, stable for consumers that filter on them.</summary>
public static class PoseDiagnosticCodes
{
    public const string MissingMotionTable = "missing-motion-table";
    public const string UnreadableMotionTable = "unreadable-motion-table";
    public const string NoDefaultState = "no-default-state";
    public const string MissingAnimation = "missing-animation";
    public const string UnreadableAnimation = "unreadable-animation";
    public const string AnimationFrame = "animation-frame";
    public const string AnimationParts = "animation-parts";
    public const string DoorMotion = "door-motion";
    public const string OpenDoorEthereal = "open-door-ethereal";
    /// <summary>The motion pose moves some part more than 1 mm or 0.1° from the placement pose.</summary>
    public const string PoseMoved = "pose-moved";
}
