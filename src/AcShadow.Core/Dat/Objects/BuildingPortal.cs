using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

public sealed record BuildingPortal(ushort Flags, ushort OtherCellId, ushort OtherPortalId, IReadOnlyList<ushort> StabList)
{
    public static BuildingPortal Read(DatBinaryReader r)
    {
        var flags = r.ReadUInt16();
        var otherCell = r.ReadUInt16();
        var otherPortal = r.ReadUInt16();
        var count = r.ReadCount(r.ReadUInt16(), 2, "stab");
        var stabs = new ushort[count];
        for (var i = 0; i < count; i++) stabs[i] = r.ReadUInt16();
        r.Align(4);
        return new BuildingPortal(flags, otherCell, otherPortal, stabs);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt16(Flags);
        w.WriteUInt16(OtherCellId);
        w.WriteUInt16(OtherPortalId);
        w.WriteUInt16((ushort)StabList.Count);
        foreach (var s in StabList) w.WriteUInt16(s);
        w.Align(4);
    }
}
