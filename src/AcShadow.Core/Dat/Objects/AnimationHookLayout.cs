namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// How many bytes each animation hook type's payload takes. A hook is stored as
/// <c>uint type, int direction, payload</c>, then zero bytes up to the next multiple of 4 (counted from the
/// object's start). acshadow never interprets a payload; it only has to step over it exactly.
/// Every payload has a fixed length except ReplaceObject's, whose part id is packed in 2 or 4 bytes.
/// </summary>
public static class AnimationHookLayout
{
    /// <summary>The hook type and direction that precede every payload.</summary>
    public const int HeaderBytes = 8;

    /// <summary>Hooks are padded to this alignment after their payload.</summary>
    public const int Alignment = 4;

    /// <summary>ReplaceObject: byte part index, then a GfxObj id as a "data id of known type" (0x01000000 base).</summary>
    private const int ReplaceObjectShortBytes = 1 + 2;
    private const int ReplaceObjectLongBytes = 1 + 4;
    private const int Variable = -1;

    // Indexed by AnimationHookType. Frame = Vector3 origin + quaternion = 28 bytes.
    private static readonly int[] PayloadBytes =
    [
        0,        // NoOp
        4,        // Sound: uint sound id
        4,        // SoundTable: uint sound type
        28,       // Attack: AttackCone = uint part index, float left x/y, float right x/y, float radius, float height
        0,        // AnimationDone
        Variable, // ReplaceObject: byte part index + packed GfxObj id (2 or 4 bytes)
        4,        // Ethereal: uint flag
        16,       // TransparentPart: uint part index, float start, end, time
        12,       // Luminous: float start, end, time
        16,       // LuminousPart: uint part index, float start, end, time
        12,       // Diffuse: float start, end, time
        16,       // DiffusePart: uint part index, float start, end, time
        8,        // Scale: float end, time
        40,       // CreateParticle: uint emitter info id, uint part index, Frame offset, uint emitter id
        4,        // DestroyParticle: uint emitter id
        4,        // StopParticle: uint emitter id
        4,        // NoDraw: uint flag
        0,        // DefaultScript
        4,        // DefaultScriptPart: uint part index
        8,        // CallPES: uint script id, float pause
        12,       // Transparent: float start, end, time
        16,       // SoundTweaked: uint sound id, three floats (probability, priority, volume)
        12,       // SetOmega: Vector3 axis
        8,        // TextureVelocity: float u speed, v speed
        12,       // TextureVelocityPart: uint part index, float u speed, v speed
        4,        // SetLight: uint flag
        40,       // CreateBlockingParticle: the retail class derives from CreateParticle and unpacks the same way
    ];

    public static bool IsKnown(AnimationHookType type) => (uint)type < (uint)PayloadBytes.Length;

    /// <summary>
    /// Reads the payload of a hook whose type and direction were just read (the padding is not read),
    /// or returns null when the type is unknown: its length cannot be known.
    /// </summary>
    public static byte[]? ReadPayload(DatBinaryReader r, AnimationHookType type)
    {
        if (!IsKnown(type)) return null;
        var length = PayloadBytes[(int)type];
        if (length != Variable) return r.ReadBytes(length);
        var head = r.ReadBytes(ReplaceObjectShortBytes);
        return HasLongDataId(head) ? [.. head, .. r.ReadBytes(ReplaceObjectLongBytes - ReplaceObjectShortBytes)] : head;
    }

    /// <summary>Whether <paramref name="payload"/> is exactly one payload of a known <paramref name="type"/>.</summary>
    public static bool Fits(AnimationHookType type, ReadOnlySpan<byte> payload)
    {
        if (!IsKnown(type)) return false;
        var length = PayloadBytes[(int)type];
        if (length != Variable) return payload.Length == length;
        return payload.Length >= ReplaceObjectShortBytes
            && payload.Length == (HasLongDataId(payload) ? ReplaceObjectLongBytes : ReplaceObjectShortBytes);
    }

    /// <summary>The packed id's first (little-endian) ushort has its top bit set when a second ushort follows.</summary>
    private static bool HasLongDataId(ReadOnlySpan<byte> replaceObjectPayload) => (replaceObjectPayload[2] & 0x80) != 0;
}
