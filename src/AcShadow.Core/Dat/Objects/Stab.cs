using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;
namespace AcShadow.Core.Dat.Objects;

/// <summary>A static object a LandBlockInfo places: a Setup or GfxObj id and its landblock frame.</summary>
public readonly record struct Stab(uint Id, Frame Frame)
{
    public static Stab Read(DatBinaryReader r) => new(r.ReadUInt32(), r.ReadFrame());

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        w.WriteFrame(Frame);
    }
}
