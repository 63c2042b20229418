using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Bsp;

/// <summary>The dump's vertex list: each vertex a physics polygon uses, once, in id order; leaf ids checked.</summary>
public sealed class BspExtractorVertexTests
{
    private static Polygon Quad(params short[] ids) => new(Stippling.NoPos, SidesType.Clockwise, 0, 0, ids, [], []);

    private static GfxObj Gfx(Dictionary<ushort, Vector3> vertices, (ushort Id, Polygon Polygon)[] polygons, params ushort[] leafPolygons) =>
        new(0x01000001, GfxObjFlags.HasPhysics, [], vertices,
            polygons.Select(p => new KeyValuePair<ushort, Polygon>(p.Id, p.Polygon)).ToArray(),
            new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 10), 0, 1, leafPolygons),
            Vector3.Zero, []);

    /// <summary>Unit square corners at z = 0 and z = 1 with ids spread over several 64-id words.</summary>
    private static Dictionary<ushort, Vector3> Corners(params ushort[] ids) =>
        ids.Select((id, i) => (id, new Vector3(i % 2, (i / 2) % 2, i / 4))).ToDictionary(p => p.id, p => p.Item2);

    [Fact]
    public void Shared_and_unordered_vertex_ids_are_listed_once_in_id_order_and_unused_ones_left_out()
    {
        var vertices = Corners(700, 3, 64, 65, 200, 130, 129, 1000);
        vertices[5] = new Vector3(9, 9, 9); // used by no polygon
        var dump = BspExtractor.Extract(Gfx(vertices,
            [(2, Quad(700, 3, 65, 64)), (0, Quad(200, 130, 1000, 129)), (1, Quad(3, 64, 130, 200))], 0, 1, 2))!;

        Assert.Equal(new[] { 3, 64, 65, 129, 130, 200, 700, 1000 }, dump.Vertices.Select(v => v.Id));
        Assert.All(dump.Vertices, v => Assert.Equal(vertices[(ushort)v.Id], v.Position));
        Assert.Equal(new[] { 0, 1, 2 }, dump.Polygons.Select(p => p.Id));
        Assert.DoesNotContain(dump.Diagnostics, d => d.Contains("not a physics polygon"));
    }

    [Fact]
    public void A_negative_vertex_id_names_the_vertex_its_ushort_key_holds_and_sorts_first()
    {
        // Vertex ids are shorts in the dat and keys are ushorts: -1 reaches key 65535. Never seen in a
        // real dat; the dump keeps the id as the polygon wrote it.
        var vertices = Corners(65535, 1, 2, 3);
        var dump = BspExtractor.Extract(Gfx(vertices, [(0, Quad(3, -1, 1, 2))], 0))!;

        Assert.Equal(new[] { -1, 1, 2, 3 }, dump.Vertices.Select(v => v.Id));
        Assert.Equal(vertices[65535], dump.Vertices[0].Position);
    }

    [Fact]
    public void A_leaf_naming_a_polygon_that_is_not_a_physics_polygon_is_a_diagnostic()
    {
        var vertices = Corners(0, 1, 2, 3);
        var dump = BspExtractor.Extract(Gfx(vertices, [(0, Quad(0, 1, 3, 2)), (70, Quad(0, 1, 3, 2))], 0, 70, 64, 71, 9000))!;

        var unknown = dump.Diagnostics.Where(d => d.Contains("is not a physics polygon")).ToArray();
        Assert.Equal(3, unknown.Length);
        Assert.Contains(unknown, d => d.Contains("polygon id 64 "));
        Assert.Contains(unknown, d => d.Contains("polygon id 71 "));
        Assert.Contains(unknown, d => d.Contains("polygon id 9000 "));
    }
}
