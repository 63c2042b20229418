using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat;

/// <summary>One 24-byte B-tree entry: where an object's block chain starts and how long it is.</summary>
public readonly record struct DatDirectoryEntry(
    ushort Flags,
    ushort Version,
    uint Id,
    int Offset,
    uint Size,
    uint RawDate,
    int Iteration)
{
    public const int Size24 = 24;

    public static DatDirectoryEntry Read(DatBinaryReader r) =>
        new(r.ReadUInt16(), r.ReadUInt16(), r.ReadUInt32(), r.ReadInt32(), r.ReadUInt32(), r.ReadUInt32(), r.ReadInt32());

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt16(Flags);
        w.WriteUInt16(Version);
        w.WriteUInt32(Id);
        w.WriteInt32(Offset);
        w.WriteUInt32(Size);
        w.WriteUInt32(RawDate);
        w.WriteInt32(Iteration);
    }
}
