using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>A static object a LandBlockInfo places: a Setup or GfxObj id and its landblock frame.</summary>
public readonly record struct Stab(uint Id, Frame Frame)
{
    public static Stab Read(DatBinaryReader r) => new(r.ReadUInt32(), Frame.Read(r));

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        Frame.Write(w);
    }
}
