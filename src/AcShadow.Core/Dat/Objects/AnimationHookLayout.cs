using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// Each animation hook type's payload, field by field. A hook is stored as <c>uint type, int direction</c>,
/// then its payload, and the next hook follows straight after: no padding, even after a ReplaceObject whose
/// long-form id leaves the next hook two bytes off a 4-byte boundary. The two public readers agree on every
/// layout here (DatReaderWriter's dats.xml, ACE's DatLoader hook classes) except CreateBlockingParticle,
/// which DatReaderWriter gives no payload and ACE reads as a CreateParticle (its class derives from that
/// hook's): ACE is followed, because it is the reader that runs against real retail dats, and because a
/// frame carrying one would lose its fields after the hook under the other reading if the payload is there.
/// NoOp has no layout in either reader (both stop at it); acshadow reads it as the bare header, a no-op
/// carrying nothing. docs/dat-layer.md lists the same table.
/// </summary>
public static class AnimationHookLayout
{
    /// <summary>The hook type and direction that precede every payload.</summary>
    public const int HeaderBytes = 8;

    private static AnimationHookField U(string name) => new(name, AnimationHookFieldKind.UInt32);
    private static AnimationHookField F(string name) => new(name, AnimationHookFieldKind.Float);
    private static AnimationHookField Id(string name) => new(name, AnimationHookFieldKind.DataId);
    private static AnimationHookField B(string name) => new(name, AnimationHookFieldKind.Bool32);

    private static readonly AnimationHookField[] None = [];
    private static readonly AnimationHookField[] Fade = [F("start"), F("end"), F("time")];
    private static readonly AnimationHookField[] PartFade = [U("partIndex"), F("start"), F("end"), F("time")];
    private static readonly AnimationHookField[] Particle =
        [Id("emitterInfoId"), U("partIndex"), new("offset", AnimationHookFieldKind.Frame), U("emitterId")];

    // Indexed by AnimationHookType.
    private static readonly AnimationHookField[][] Layouts =
    [
        None,                                                                   // NoOp
        [Id("soundId")],                                                        // Sound
        [U("soundType")],                                                       // SoundTable
        [U("partIndex"), F("leftX"), F("leftY"), F("rightX"), F("rightY"), F("radius"), F("height")], // Attack (AttackCone)
        None,                                                                   // AnimationDone
        [new("partIndex", AnimationHookFieldKind.UInt16), new("gfxObjId", AnimationHookFieldKind.PackedGfxObjId)], // ReplaceObject
        [B("ethereal")],                                                        // Ethereal
        PartFade,                                                               // TransparentPart
        Fade,                                                                   // Luminous
        PartFade,                                                               // LuminousPart
        Fade,                                                                   // Diffuse
        PartFade,                                                               // DiffusePart
        [F("end"), F("time")],                                                  // Scale
        Particle,                                                               // CreateParticle
        [U("emitterId")],                                                       // DestroyParticle
        [U("emitterId")],                                                       // StopParticle
        [B("noDraw")],                                                          // NoDraw
        None,                                                                   // DefaultScript
        [U("partIndex")],                                                       // DefaultScriptPart
        [Id("scriptId"), F("pause")],                                           // CallPES (a PhysicsScript id)
        Fade,                                                                   // Transparent
        [Id("soundId"), F("priority"), F("probability"), F("volume")],          // SoundTweaked
        [new("axis", AnimationHookFieldKind.Vector3)],                          // SetOmega
        [F("uSpeed"), F("vSpeed")],                                             // TextureVelocity
        [U("partIndex"), F("uSpeed"), F("vSpeed")],                             // TextureVelocityPart
        [B("lightsOn")],                                                        // SetLight
        Particle,                                                               // CreateBlockingParticle: as CreateParticle (ACE)
    ];

    public static bool IsKnown(AnimationHookType type) => (uint)type < (uint)Layouts.Length;

    /// <summary>The payload's fields in stored order; an unknown type has none to give.</summary>
    public static IReadOnlyList<AnimationHookField> Fields(AnimationHookType type) =>
        IsKnown(type) ? Layouts[(int)type] : throw new ArgumentOutOfRangeException(nameof(type), type, "no known layout");

    /// <summary>
    /// Reads the payload of a hook whose type and direction were just read, or returns null when the type is
    /// unknown: its length cannot be known.
    /// </summary>
    public static byte[]? ReadPayload(DatBinaryReader r, AnimationHookType type)
    {
        if (!IsKnown(type)) return null;
        var length = 0;
        foreach (var field in Layouts[(int)type])
        {
            length += field.MinBytes;
            if (field.Kind == AnimationHookFieldKind.PackedGfxObjId && IsLongForm(r.Peek(length)[^1])) length += 2;
        }
        return r.ReadBytes(length);
    }

    /// <summary>Whether <paramref name="payload"/> is exactly one payload of a known <paramref name="type"/>.</summary>
    public static bool Fits(AnimationHookType type, ReadOnlySpan<byte> payload)
    {
        if (!IsKnown(type)) return false;
        var length = 0;
        foreach (var field in Layouts[(int)type])
        {
            length += field.MinBytes;
            if (length > payload.Length) return false;
            if (field.Kind == AnimationHookFieldKind.PackedGfxObjId && IsLongForm(payload[length - 1])) length += 2;
        }
        return payload.Length == length;
    }

    /// <summary>The packed id's first (little-endian) ushort has its top bit set when a second ushort follows.</summary>
    private static bool IsLongForm(byte firstUShortHighByte) => (firstUShortHighByte & 0x80) != 0;
}
