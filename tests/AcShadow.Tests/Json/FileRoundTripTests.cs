using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Json;

public class FileRoundTripTests
{
    [Fact]
    public void Every_sample_bsp_dump_reads_back_to_the_same_tree()
    {
        using var dat = SampleDat.OpenPortal();
        var dumps = dat.ListIds(DatObjectKind.GfxObj).Select(id => BspExtractor.Extract(dat.ReadGfxObj(id)!)).OfType<BspDump>().ToArray();
        Assert.True(dumps.Length >= 10);
        foreach (var dump in dumps)
        {
            var bytes = BspFileWriter.Write(dump);
            var back = BspFileReader.Read(System.Text.Encoding.UTF8.GetString(bytes));
            Assert.Equal(dump.GfxObjId, back.GfxObjId);
            Assert.Equal(dump.BoundingSphere, back.BoundingSphere);
            Assert.Equal(dump.Vertices, back.Vertices);
            Assert.Equal(dump.Polygons.Select(p => (p.Id, p.Plane, p.SidesType, p.Stippling, string.Join(',', p.VertexIds))),
                back.Polygons.Select(p => (p.Id, p.Plane, p.SidesType, p.Stippling, string.Join(',', p.VertexIds))));
            Assert.Equal(dump.Nodes.Select(Describe), back.Nodes.Select(Describe));
            // -0 is written as 0 by design; == treats them as equal, so compare planes by value.
            Assert.True(dump.Nodes.Zip(back.Nodes).All(p => p.First.Plane == p.Second.Plane));
            Assert.Equal(bytes, BspFileWriter.Write(back));
        }
    }

    [Fact]
    public void Every_sample_shadow_file_reads_back_to_the_same_shapes()
    {
        using var dat = SampleDat.OpenPortal();
        foreach (var id in dat.ListIds(DatObjectKind.Setup))
        foreach (var policy in new[] { ShapePolicy.Retail, ShapePolicy.Union })
        {
            var setup = dat.ReadSetup(id)!;
            var set = ShadowShapeBuilder.Build(setup, dat.ReadGfxObj, new ShapeBuildOptions(policy, 1.25f));
            var back = ShadowFileReader.Read(System.Text.Encoding.UTF8.GetString(ShadowFileWriter.Write(setup, set)));
            Assert.Equal(set.Shapes, back.Shapes);
            Assert.Equal(set.Diagnostics, back.Diagnostics);
            Assert.Equal(set.Placement.Used, back.Placement.Used);
            Assert.Equal(set.EntityScale, back.EntityScale);
        }
    }

    [Fact]
    public void Degenerate_and_non_planar_polygons_are_named_in_the_dump()
    {
        using var dat = SampleDat.OpenPortal();
        var dump = BspExtractor.Extract(dat.ReadGfxObj(0x01006000)!)!;
        Assert.Equal([6], dump.Stats.DegeneratePolygons);
        Assert.Equal([7], dump.Stats.NonPlanarPolygons);
        Assert.Null(dump.Polygons.Single(p => p.Id == 6).Plane);
        Assert.Contains(dump.Diagnostics, d => d.Contains("polygon 6") && d.Contains("degenerate"));
        Assert.Contains(dump.Diagnostics, d => d.Contains("polygon 7") && d.Contains("non-planar"));
        Assert.Contains("\"plane\": null", System.Text.Encoding.UTF8.GetString(BspFileWriter.Write(dump)));
    }

    [Fact]
    public void Dump_lists_only_vertices_the_physics_polygons_use_and_a_preorder_tree()
    {
        using var dat = SampleDat.OpenPortal();
        var dump = BspExtractor.Extract(dat.ReadGfxObj(0x01005000)!)!;
        var used = dump.Polygons.SelectMany(p => p.VertexIds).ToHashSet();
        Assert.Equal(used.Order(), dump.Vertices.Select(v => v.Id));
        Assert.True(dump.Polygons.Count >= 200);
        for (var i = 0; i < dump.Nodes.Count; i++)
        {
            var node = dump.Nodes[i];
            Assert.Equal(i, node.Index);
            if (node.Pos is { } pos) Assert.True(pos > i);
            if (node.Neg is { } neg) Assert.True(neg > (node.Pos ?? i));
        }
    }

    private static string Describe(BspNode n) =>
        $"{n.Index} {n.Type} {n.Sphere} {n.Pos} {n.Neg} {n.LeafIndex} {n.Solid} {string.Join(',', n.PolygonIds)}";
}
