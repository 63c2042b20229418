using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;
namespace AcShadow.Core.Dat.Objects;

/// <summary>A building a LandBlockInfo places: its model (Setup or GfxObj), frame and portals.</summary>
public sealed record BuildingInfo(uint ModelId, Frame Frame, uint NumLeaves, IReadOnlyList<BuildingPortal> Portals)
{
    public static BuildingInfo Read(DatBinaryReader r)
    {
        var model = r.ReadUInt32();
        var frame = r.ReadFrame();
        var leaves = r.ReadUInt32();
        var count = r.ReadCount(r.ReadUInt32(), 8, "building portal");
        var portals = new BuildingPortal[count];
        for (var i = 0; i < count; i++) portals[i] = BuildingPortal.Read(r);
        return new BuildingInfo(model, frame, leaves, portals);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(ModelId);
        w.WriteFrame(Frame);
        w.WriteUInt32(NumLeaves);
        w.WriteUInt32((uint)Portals.Count);
        foreach (var p in Portals) p.Write(w);
    }
}
