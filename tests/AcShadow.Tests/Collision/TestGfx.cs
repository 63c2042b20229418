using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Tests.Collision;

/// <summary>GfxObjs made from test meshes, and a real dat written and read back through DatDatabase.</summary>
public static class TestGfx
{
    public static GfxObj Make(uint id, TestMesh mesh, PhysicsBspNode? bsp = null)
    {
        var vertices = new Dictionary<ushort, Vector3>();
        for (var i = 0; i < mesh.Vertices.Count; i++) vertices[(ushort)i] = mesh.Vertices[i];
        var polygons = mesh.Polygons.Select((p, i) =>
            new KeyValuePair<ushort, Polygon>((ushort)i, new Polygon(Stippling.NoPos, SidesType.Clockwise, 0, 0, p, [], []))).ToArray();
        return new GfxObj(id, GfxObjFlags.HasPhysics, [], vertices, polygons, bsp ?? TestBspBuilder.Build(mesh), Vector3.Zero, []);
    }

    public static BspDump Dump(uint id, TestMesh mesh, PhysicsBspNode? bsp = null) => BspExtractor.Extract(Make(id, mesh, bsp))!;

    /// <summary>Writes the objects into a portal dat and opens it again, so tests see what the reader decodes.</summary>
    public static DatDatabase RoundTrip(IEnumerable<GfxObj> gfxObjs, IEnumerable<Setup>? setups = null)
    {
        var objects = new Dictionary<uint, byte[]>();
        foreach (var g in gfxObjs) { var w = new DatBinaryWriter(); g.Write(w); objects[g.Id] = w.ToArray(); }
        foreach (var s in setups ?? []) { var w = new DatBinaryWriter(); s.Write(w); objects[s.Id] = w.ToArray(); }
        var bytes = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal));
        return DatDatabase.Open(new MemoryStream(bytes), "test_portal.dat");
    }
}
