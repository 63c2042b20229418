namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// The motion command values a pose needs (retail MotionCommand; ACE MotionStance/MotionCommand) and the
/// table key they form. A style (stance) has bit 0x80000000; a substate such as a door's On/Off bit 0x40000000.
/// </summary>
public static class MotionCommand
{
    public const uint NonCombat = 0x8000003D;
    /// <summary>A door's open substate.</summary>
    public const uint On = 0x4000000B;
    /// <summary>A door's closed substate.</summary>
    public const uint Off = 0x4000000C;
    public const uint Ready = 0x41000003;

    /// <summary>
    /// CMotionTable's key for (style, motion): (style &lt;&lt; 16) | (motion &amp; 0xFFFFFF) in 32-bit unsigned
    /// arithmetic, so only the style's low 16 bits survive (NonCombat + Off = 0x003D000C).
    /// </summary>
    public static uint Key(uint style, uint motion) => unchecked((style << 16) | (motion & 0xFFFFFF));
}
