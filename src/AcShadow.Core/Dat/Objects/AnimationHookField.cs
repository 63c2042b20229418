namespace AcShadow.Core.Dat.Objects;

/// <summary>How one field of an animation hook's payload is stored.</summary>
public enum AnimationHookFieldKind
{
    /// <summary>uint32 (part indexes, emitter ids, sound types, script ids).</summary>
    UInt32,
    /// <summary>uint32 holding a full data id (a Wave, a ParticleEmitter).</summary>
    DataId,
    /// <summary>uint32, 0 false, anything else true.</summary>
    Bool32,
    Float,
    /// <summary>uint16 (ReplaceObject's part index).</summary>
    UInt16,
    /// <summary>
    /// A GfxObj id packed as an offset from 0x01000000: one ushort when its top bit is clear (offsets up to
    /// 0x7FFF), else that ushort's low 14 bits are the offset's bits 16..29 and a second ushort holds bits 0..15.
    /// </summary>
    PackedGfxObjId,
    /// <summary>Three floats x, y, z.</summary>
    Vector3,
    /// <summary>Origin (three floats), then orientation W, X, Y, Z: 28 bytes.</summary>
    Frame,
}

/// <summary>One named field of a hook payload, in the order the dat stores it.</summary>
public readonly record struct AnimationHookField(string Name, AnimationHookFieldKind Kind)
{
    /// <summary>The GfxObj id space a <see cref="AnimationHookFieldKind.PackedGfxObjId"/> is packed against.</summary>
    public const uint GfxObjBase = 0x01000000;

    /// <summary>Bytes the field takes; a packed id takes 2 or 4 (this is its short length).</summary>
    public int MinBytes => Kind switch
    {
        AnimationHookFieldKind.UInt16 or AnimationHookFieldKind.PackedGfxObjId => 2,
        AnimationHookFieldKind.Vector3 => 12,
        AnimationHookFieldKind.Frame => 28,
        _ => 4,
    };
}
