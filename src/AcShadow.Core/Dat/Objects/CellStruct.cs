using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One cell shape of an Environment: vertices, the drawing polygons (portal polygons are among them:
/// a cell portal names its polygon by a drawing polygon id, as ACE's EnvCell looks it up), the ids of
/// the portal polygons, the cell BSP, the physics polygons and the PhysicsBSP. Layout (DatReaderWriter's
/// dats.xml CellStruct, ACE's CellStruct.Unpack): polygon, physics polygon and portal counts (uint
/// each); the vertex array (as a GfxObj's); the drawing polygons (ushort id + polygon each); the portal
/// ids (ushort each); padding to 4 bytes; the cell BSP; the physics polygons; the PhysicsBSP; a uint
/// that says whether a drawing BSP follows, and that tree; padding to 4 bytes. Vertex normals and UVs
/// and the drawing BSP are stepped over, not kept.
/// </summary>
public sealed record CellStruct(
    IReadOnlyDictionary<ushort, Vector3> Vertices,
    IReadOnlyList<KeyValuePair<ushort, Polygon>> Polygons,
    IReadOnlyList<ushort> Portals,
    CellBspNode CellBsp,
    IReadOnlyList<KeyValuePair<ushort, Polygon>> PhysicsPolygons,
    PhysicsBspNode PhysicsBsp,
    bool HasDrawingBsp)
{
    public static CellStruct Read(DatBinaryReader r)
    {
        var polygonCount = r.ReadUInt32();
        var physicsCount = r.ReadUInt32();
        var portalCount = r.ReadUInt32();
        var vertices = VertexArrayLayout.Read(r);
        var polygons = ReadPolygons(r, polygonCount, "polygon");
        var portals = new ushort[r.ReadCount(portalCount, 2, "portal")];
        for (var i = 0; i < portals.Length; i++) portals[i] = r.ReadUInt16();
        r.Align(4);
        var cellBsp = CellBspNode.Read(r);
        var physics = ReadPolygons(r, physicsCount, "physics polygon");
        var physicsBsp = PhysicsBspNode.Read(r);
        var hasDrawing = r.ReadUInt32() != 0;
        if (hasDrawing) DrawingBsp.Skip(r);
        r.Align(4);
        return new CellStruct(vertices, polygons, portals, cellBsp, physics, physicsBsp, hasDrawing);
    }

    private static List<KeyValuePair<ushort, Polygon>> ReadPolygons(DatBinaryReader r, uint count, string what)
    {
        var list = new List<KeyValuePair<ushort, Polygon>>(r.ReadCount(count, 12, what));
        for (var i = 0; i < (int)count; i++)
        {
            var key = r.ReadUInt16();
            list.Add(new(key, Polygon.Read(r)));
        }
        return list;
    }

    /// <summary>Vertices without normals or UVs; with <see cref="HasDrawingBsp"/>, a one-leaf drawing BSP.</summary>
    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)Polygons.Count);
        w.WriteUInt32((uint)PhysicsPolygons.Count);
        w.WriteUInt32((uint)Portals.Count);
        VertexArrayLayout.Write(w, Vertices);
        foreach (var (key, polygon) in Polygons)
        {
            w.WriteUInt16(key);
            polygon.Write(w);
        }
        foreach (var p in Portals) w.WriteUInt16(p);
        w.Align(4);
        CellBsp.Write(w);
        foreach (var (key, polygon) in PhysicsPolygons)
        {
            w.WriteUInt16(key);
            polygon.Write(w);
        }
        PhysicsBsp.Write(w);
        w.WriteUInt32(HasDrawingBsp ? 1u : 0u);
        if (HasDrawingBsp) DrawingBsp.WriteOneLeaf(w);
        w.Align(4);
    }
}
