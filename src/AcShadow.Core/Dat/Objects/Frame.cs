using System.Numerics;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Core.Dat.Objects;

/// <summary>An origin and an orientation (stored W, X, Y, Z in the dat).</summary>
public readonly record struct Frame(Vector3 Origin, Quaternion Orientation)
{
    public static readonly Frame Identity = new(Vector3.Zero, Quaternion.Identity);

    public static Frame Read(DatBinaryReader r) => new(r.ReadVector3(), r.ReadQuaternion());

    public void Write(DatBinaryWriter w)
    {
        w.WriteVector3(Origin);
        w.WriteQuaternion(Orientation);
    }
}
