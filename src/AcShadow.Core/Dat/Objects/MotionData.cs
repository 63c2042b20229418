using System.Numerics;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// What a motion plays: its animations in order, and the velocity and spin it gives the object while it
/// plays (neither poses a part). Stored as NumAnims u8, Bitfield u8, Flags u8 (0x1 velocity, 0x2 omega),
/// zero bytes to a 4-byte boundary counted from the object's start, the AnimData, then the vectors.
/// </summary>
public sealed record MotionData(byte Bitfield, IReadOnlyList<AnimData> Anims, Vector3? Velocity, Vector3? Omega)
{
    private const byte HasVelocity = 0x1, HasOmega = 0x2;

    /// <summary>The three header bytes and their padding: the least a MotionData can take.</summary>
    public const int MinBytes = 4;

    public static MotionData Read(DatBinaryReader r)
    {
        var count = r.ReadByte();
        var bitfield = r.ReadByte();
        var flags = r.ReadByte();
        r.Align(4);
        var anims = new AnimData[r.ReadCount(count, AnimData.Bytes, "animation")];
        for (var i = 0; i < anims.Length; i++) anims[i] = AnimData.Read(r);
        Vector3? velocity = (flags & HasVelocity) != 0 ? r.ReadVector3() : null;
        Vector3? omega = (flags & HasOmega) != 0 ? r.ReadVector3() : null;
        return new MotionData(bitfield, anims, velocity, omega);
    }

    public void Write(DatBinaryWriter w)
    {
        if (Anims.Count > byte.MaxValue) throw new InvalidOperationException($"a MotionData stores at most {byte.MaxValue} animations, not {Anims.Count}");
        w.WriteByte((byte)Anims.Count);
        w.WriteByte(Bitfield);
        w.WriteByte((byte)((Velocity is null ? 0 : HasVelocity) | (Omega is null ? 0 : HasOmega)));
        w.Align(4);
        foreach (var a in Anims) a.Write(w);
        if (Velocity is { } v) w.WriteVector3(v);
        if (Omega is { } o) w.WriteVector3(o);
    }
}
