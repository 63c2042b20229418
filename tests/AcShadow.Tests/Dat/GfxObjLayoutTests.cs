using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Tests.Dat;

/// <summary>
/// GfxObj bytes laid out by hand from the public layout (DatReaderWriter dats.xml GfxObj, VertexArray, SWVertex,
/// Polygon, PhysicsBSPNode; ACE DatLoader agrees), not by our writer: the vertex ids as a dat may hold them, and the
/// drawing-only bytes the reader steps over (vertex normals and UVs, polygon UV indices) of the right length, shown
/// by every field read after them.
/// </summary>
public class GfxObjLayoutTests
{
    private static readonly Vector3 A = new(1f, 2f, 3f), B = new(-4f, 0.5f, 0f), C = new(0f, 0f, 7.25f);

    [Fact]
    public void Vertex_ids_running_from_0_read_by_index_and_enumerate_in_order()
    {
        var gfx = GfxObj.Read(new DatBinaryReader(Bytes([(0, A), (1, B), (2, C)])));
        Assert.Equal([new(0, A), new(1, B), new KeyValuePair<ushort, Vector3>(2, C)], gfx.Vertices);
        Assert.True(gfx.Vertices.TryGetValue(2, out var c) && c == C);
        Assert.False(gfx.Vertices.ContainsKey(3));
        AssertTheRestRead(gfx);
    }

    [Fact]
    public void Vertex_ids_in_another_order_or_with_gaps_read_by_id_in_stored_order()
    {
        var gfx = GfxObj.Read(new DatBinaryReader(Bytes([(0, A), (5, B), (2, C)])));
        Assert.Equal([new(0, A), new(5, B), new KeyValuePair<ushort, Vector3>(2, C)], gfx.Vertices);
        Assert.True(gfx.Vertices.TryGetValue(5, out var b) && b == B);
        Assert.False(gfx.Vertices.ContainsKey(1));
        AssertTheRestRead(gfx, polygonIds: [0, 5, 2]);
    }

    [Fact]
    public void A_repeated_vertex_id_keeps_its_first_place_and_its_last_origin()
    {
        var gfx = GfxObj.Read(new DatBinaryReader(Bytes([(0, A), (1, B), (1, C)])));
        Assert.Equal([new(0, A), new KeyValuePair<ushort, Vector3>(1, C)], gfx.Vertices);
        AssertTheRestRead(gfx, polygonIds: [0, 1, 1]);
    }

    private static void AssertTheRestRead(GfxObj gfx, short[]? polygonIds = null)
    {
        Assert.Equal(0x01000ABCu, gfx.Id);
        var (key, polygon) = Assert.Single(gfx.PhysicsPolygons);
        Assert.Equal(7, key);
        Assert.Equal(polygonIds ?? [0, 1, 2], polygon.VertexIds);
        Assert.Equal(SidesType.Clockwise, polygon.SidesType);
        Assert.Equal((short)3, polygon.PosSurface);
        Assert.Empty(polygon.PosUVIndices);
        Assert.Empty(polygon.NegUVIndices);
        var leaf = Assert.IsType<PhysicsBspNode>(gfx.PhysicsBsp);
        Assert.Equal(BspNodeType.Leaf, leaf.Type);
        Assert.Equal(1, leaf.Solid);
        Assert.Equal([(ushort)7], leaf.Polygons);
        Assert.Equal(new Vector3(0.5f, 0.25f, 2f), gfx.SortCenter);
    }

    /// <summary>
    /// id, flags (HasPhysics), surfaces (compressed count 0); VertexArray: type 1, count, then each vertex's id
    /// (ushort), UV count (ushort: 1 here, 8 bytes of UV), origin, normal; one physics polygon keyed 7: 3 points,
    /// stippling 0, sides Clockwise (so both UV index lists, 3 bytes each), surfaces 3 and 0, its vertex ids; the
    /// PhysicsBSP, one solid leaf ("LEAF", index 0, solid 1, sphere, polygon 7); the sort centre.
    /// </summary>
    private static byte[] Bytes((ushort Id, Vector3 Origin)[] vertices)
    {
        using var stream = new MemoryStream();
        using var w = new BinaryWriter(stream);
        w.Write(0x01000ABCu);
        w.Write(1u);
        w.Write((byte)0);
        w.Write(1);
        w.Write((uint)vertices.Length);
        foreach (var (id, origin) in vertices)
        {
            w.Write(id);
            w.Write((ushort)1);
            Write(w, origin);
            Write(w, Vector3.UnitZ);
            w.Write(0.25f);
            w.Write(0.75f);
        }
        w.Write((byte)1);
        w.Write((ushort)7);
        w.Write((byte)3);
        w.Write((byte)0);
        w.Write(2);
        w.Write((short)3);
        w.Write((short)0);
        foreach (var (id, _) in vertices) w.Write((short)id);
        w.Write(new byte[] { 9, 8, 7 });
        w.Write(new byte[] { 6, 5, 4 });
        w.Write(0x4C454146u);
        w.Write(0);
        w.Write(1);
        Write(w, Vector3.Zero);
        w.Write(10f);
        w.Write(1u);
        w.Write((ushort)7);
        Write(w, new Vector3(0.5f, 0.25f, 2f));
        w.Flush();
        return stream.ToArray();
    }

    private static void Write(BinaryWriter w, Vector3 v)
    {
        w.Write(v.X);
        w.Write(v.Y);
        w.Write(v.Z);
    }
}
