using System.Numerics;

namespace AcShadow.Core.Dat.Objects;

public readonly record struct Sphere(Vector3 Center, float Radius)
{
    public static Sphere Read(DatBinaryReader r) => new(r.ReadVector3(), r.ReadSingle());

    public void Write(DatBinaryWriter w)
    {
        w.WriteVector3(Center);
        w.WriteSingle(Radius);
    }
}
