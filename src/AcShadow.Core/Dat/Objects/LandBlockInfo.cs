using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A landblock's static content (cell dat id 0xXXYYFFFE): static objects (Stabs) and buildings,
/// each with a frame relative to the landblock's corner.
/// </summary>
public sealed record LandBlockInfo(
    uint Id,
    uint NumCells,
    IReadOnlyList<Stab> Objects,
    IReadOnlyList<BuildingInfo> Buildings,
    IReadOnlyList<KeyValuePair<uint, uint>> RestrictionTable)
{
    public static LandBlockInfo Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var cells = r.ReadUInt32();
        var objectCount = r.ReadCount(r.ReadUInt32(), 32, "static object");
        var objects = new Stab[objectCount];
        for (var i = 0; i < objectCount; i++) objects[i] = Stab.Read(r);
        var buildingCount = r.ReadUInt16();
        var hasRestrictions = r.ReadUInt16() != 0;
        // Model id, frame, leaf count and portal count: 40 bytes at least per building.
        var buildings = new BuildingInfo[r.ReadCount(buildingCount, 40, "building")];
        for (var i = 0; i < buildingCount; i++) buildings[i] = BuildingInfo.Read(r);
        var restrictions = new List<KeyValuePair<uint, uint>>();
        if (hasRestrictions)
        {
            var count = r.ReadCount(r.ReadUInt16(), 8, "restriction");
            r.ReadUInt16(); // bucket count
            for (var i = 0; i < count; i++) restrictions.Add(new(r.ReadUInt32(), r.ReadUInt32()));
        }
        return new LandBlockInfo(id, cells, objects, buildings, restrictions);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        w.WriteUInt32(NumCells);
        w.WriteUInt32((uint)Objects.Count);
        foreach (var o in Objects) o.Write(w);
        w.WriteUInt16((ushort)Buildings.Count);
        w.WriteUInt16((ushort)(RestrictionTable.Count > 0 ? 1 : 0));
        foreach (var b in Buildings) b.Write(w);
        if (RestrictionTable.Count > 0)
        {
            w.WriteUInt16((ushort)RestrictionTable.Count);
            w.WriteUInt16(8);
            foreach (var (k, v) in RestrictionTable) { w.WriteUInt32(k); w.WriteUInt32(v); }
        }
    }
}
