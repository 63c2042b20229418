using System.Numerics;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Core.Dat.Objects;

/// <summary>A vertical cylinder: base centre, radius, height.</summary>
public readonly record struct CylSphere(Vector3 Origin, float Radius, float Height)
{
    public static CylSphere Read(DatBinaryReader r) => new(r.ReadVector3(), r.ReadSingle(), r.ReadSingle());

    public void Write(DatBinaryWriter w)
    {
        w.WriteVector3(Origin);
        w.WriteSingle(Radius);
        w.WriteSingle(Height);
    }
}
