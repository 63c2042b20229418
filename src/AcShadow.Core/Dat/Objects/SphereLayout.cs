using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A sphere's dat layout: centre (3 floats) then radius. Kept beside the dat layer so <see cref="Sphere"/>
/// itself can live in the fixtures library, which knows nothing of dat files.
/// </summary>
public static class SphereLayout
{
    extension(Sphere)
    {
        public static Sphere Read(DatBinaryReader r) => new(r.ReadVector3(), r.ReadSingle());
    }

    extension(Sphere sphere)
    {
        public void Write(DatBinaryWriter w)
        {
            w.WriteVector3(sphere.Center);
            w.WriteSingle(sphere.Radius);
        }
    }
}
