using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Tests.Collision;

/// <summary>Degenerate geometry and inputs never crash a query; each problem is reported, naming the polygon, node or part.</summary>
public class DegenerateInputTests
{
    private static readonly (Vector3, float)[] OddProbes =
    [
        (new(float.NaN, 0, 0), 0.5f), (new(0, float.PositiveInfinity, 0), 0.5f), (Vector3.Zero, float.NaN),
        (Vector3.Zero, -1f), (Vector3.Zero, 0f), (Vector3.Zero, float.Epsilon), (new(0.5f, 0, 1), PhysicsEpsilon.Value),
        (new(1e30f, -1e30f, 1e30f), 1e30f), (Vector3.Zero, float.MaxValue),
    ];

    [Fact]
    public void Collinear_repeated_and_non_planar_polygons_are_reported_by_id_and_never_crash()
    {
        var mesh = TestMesh.Box(new(0, 0, 1), new(0.5f, 0.5f, 0.5f))
            .WithPolygon([-1, -2, -3], new(2, 0, 0), new(3, 0, 0), new(4, 0, 0))              // collinear: polygon 6
            .WithPolygon([-1, -1, -2, -3], new(2, 1, 0), new(3, 1, 0), new(3, 2, 0))          // repeated vertex: polygon 7
            .WithPolygon([-1, -2, -3, -4], new(2, 3, 0), new(3, 3, 0.4f), new(3, 4, 0), new(2, 4, 0.4f)); // non-planar: polygon 8
        var dump = TestGfx.Dump(0x01007100, mesh);
        var bsp = CompiledBsp.Compile(dump);
        Assert.Contains(bsp.Diagnostics, d => d.Code == CollisionDiagnosticCodes.SkippedPolygon && d.Message.Contains("polygon 6"));
        Assert.Contains(bsp.Diagnostics, d => d.Code == CollisionDiagnosticCodes.NonPlanarPolygon && d.Message.Contains("polygon 8"));
        Assert.DoesNotContain(bsp.Polygons, p => p.Id == 6);
        RunEverything(bsp);
    }

    [Fact]
    public void The_sample_part_with_a_degenerate_and_a_non_planar_polygon_is_reported_and_queried()
    {
        var dump = CollisionCorpus.Sample.Single(d => d.GfxObjId == 0x01006000);
        var bsp = CompiledBsp.Compile(dump);
        Assert.Contains(bsp.Diagnostics, d => d.Code == CollisionDiagnosticCodes.SkippedPolygon && d.Message.Contains("0x01006000 polygon 6"));
        Assert.Contains(bsp.Diagnostics, d => d.Code == CollisionDiagnosticCodes.NonPlanarPolygon && d.Message.Contains("0x01006000 polygon 7"));
        RunEverything(bsp);
    }

    [Fact]
    public void Malformed_trees_are_repaired_as_stated_and_reported_by_node()
    {
        var plane = new Plane(Vector3.UnitZ, -1f);
        var sphere = new Sphere(new Vector3(0, 0, 1), 2f);
        BspPolygon Poly(int id, params int[] v) => new(id, v, PolygonPlaneOf(v), SidesType.Clockwise, Stippling.NoPos);
        Plane? PolygonPlaneOf(int[] v) => v.Length >= 3 ? plane : null;
        BspVertex[] vertices = [new(0, new(-1, -1, 1)), new(1, new(1, -1, 1)), new(2, new(1, 1, 1)), new(3, new(-1, 1, 1)), new(4, new(float.NaN, 0, 1))];
        BspPolygon[] polygons = [Poly(0, 0, 1, 2, 3), Poly(1, 0, 1, 9), Poly(2, 0, 1, 4), Poly(3, 0, 1), new(4, [0, 1, 2], new Plane(new Vector3(float.NaN, 0, 0), 0), SidesType.Clockwise, Stippling.NoPos)];
        BspNode[] nodes =
        [
            new(0, BspNodeType.BPIN, plane, sphere, 1, 0, 0, false, []),                                    // neg child points at itself
            new(1, BspNodeType.BPIN, null, new Sphere(new(float.NaN, 0, 0), 1), 2, 99, 0, false, []),       // no plane, NaN sphere, child out of range
            new(2, BspNodeType.BPIN, new Plane(new Vector3(0, float.NaN, 0), 0), sphere, 3, 3, 0, false, []),// NaN plane, the same child twice
            new(3, BspNodeType.Leaf, null, sphere, null, null, 0, true, [0, 1, 2, 3, 4, 77]),              // a missing polygon id
            new(4, BspNodeType.Leaf, null, sphere, null, null, 1, true, []),                                 // unreachable, inert
        ];
        var dump = new BspDump(0x01007200, sphere, vertices, polygons, nodes, new BspStats(5, 5, 5, 2, 2, 3, [], []), []);
        var bsp = CompiledBsp.Compile(dump);
        var messages = string.Join("\n", bsp.Diagnostics);
        Assert.Contains("node 0: negative child index 0 does not come after its parent", messages);
        Assert.Contains("node 1: internal node without a finite splitting plane", messages);
        Assert.Contains("node 1: non-finite bounding sphere", messages);
        Assert.Contains("node 1: negative child index 99 is out of range", messages);
        Assert.Contains("node 2: internal node without a finite splitting plane", messages);
        Assert.Contains("node 2: negative child index 3 is already another node's child", messages);
        Assert.Contains("polygon id 77 is not a physics polygon", messages);
        Assert.Contains("polygon 1: vertex id 9 is not in the vertex list", messages);
        Assert.Contains("polygon 2: vertex 4 is not finite", messages);
        Assert.Contains("polygon 3: degenerate", messages);
        Assert.Contains("polygon 4: non-finite plane", messages);
        Assert.Contains("1 node(s) cannot be reached from the root", messages);
        Assert.Contains("solid leaf/leaves hold no polygons", messages);
        RunEverything(bsp);
        // The repaired tree still answers: the quad at z = 1 blocks a sphere resting on it.
        Assert.True(new BspSphereQuery(bsp).Overlaps(new Vector3(0, 0, 1.4f), 0.5f));
    }

    [Fact]
    public void An_empty_tree_blocks_nothing_and_says_so()
    {
        var dump = new BspDump(0x01007300, new Sphere(Vector3.Zero, 1), [], [], [], new BspStats(0, 0, 0, 0, 0, 0, [], []), []);
        var bsp = CompiledBsp.Compile(dump);
        Assert.Contains(bsp.Diagnostics, d => d.Code == CollisionDiagnosticCodes.EmptyTree);
        RunEverything(bsp);
    }

    [Fact]
    public void Odd_probes_never_block_when_not_finite_and_never_throw()
    {
        var bsp = CompiledBsp.Compile(TestGfx.Dump(0x01007400, TestMesh.Box(new(0, 0, 1), new(0.5f, 0.5f, 0.5f))));
        var reference = new BspSphereQuery(bsp);
        Assert.False(reference.Overlaps(new Vector3(float.NaN, 0, 1), 10f));
        Assert.False(reference.Overlaps(new Vector3(0, 0, 1), float.NaN));
        Assert.False(reference.Overlaps(new Vector3(0, 0, 1), -0.5f));
        Assert.False(reference.Overlaps(new Vector3(0, 0, 1), float.PositiveInfinity));
        RunEverything(bsp);
    }

    [Fact]
    public void Unusable_shapes_are_skipped_and_named()
    {
        var bsp = CompiledBsp.Compile(TestGfx.Dump(0x01007500, TestMesh.Box(new(0, 0, 1), new(0.5f, 0.5f, 0.5f))));
        CompiledBsp? Lookup(uint id) => id == bsp.GfxObjId ? bsp : null;
        ShadowShape Part(int i, uint id, Vector3 p, Quaternion q, float scale) => new(ShapeSource.Part, i, id, CollisionType.Bsp, p, q, scale, 1f, 0f, null);
        ShadowShape[] shapes =
        [
            Part(0, bsp.GfxObjId, new(float.NaN, 0, 0), Quaternion.Identity, 1f),
            Part(1, bsp.GfxObjId, Vector3.Zero, new Quaternion(float.NaN, 0, 0, 1), 1f),
            Part(2, bsp.GfxObjId, Vector3.Zero, Quaternion.Identity, 0f),
            Part(3, bsp.GfxObjId, Vector3.Zero, default, 1f),
            Part(4, 0x0100BEEF, Vector3.Zero, Quaternion.Identity, 1f),
            Part(5, bsp.GfxObjId, new(5, 0, 0), new Quaternion(0, 0, 0, 2), 1f),
            new(ShapeSource.CylSphere, 0, null, CollisionType.Cylinder, new(0, 0, float.PositiveInfinity), Quaternion.Identity, 1f, 0.5f, 1f, null),
            new(ShapeSource.Sphere, 0, null, CollisionType.Sphere, new(9, 9, 0), Quaternion.Identity, 1f, 0f, 0f, null),
        ];
        var query = ObjectOverlapQuery.Create(shapes, Lookup);
        var messages = string.Join("\n", query.Diagnostics);
        Assert.Contains("part 0 (GfxObj 0x01007500): NaN or infinity in its position", messages);
        Assert.Contains("part 1 (GfxObj 0x01007500): NaN or infinity in its rotation", messages);
        Assert.Contains("part 2 (GfxObj 0x01007500): scale 0 cannot be divided by", messages);
        Assert.Contains("part 3 (GfxObj 0x01007500): zero rotation quaternion", messages);
        Assert.Contains("part 4 (GfxObj 0x0100BEEF): no PhysicsBSP", messages);
        Assert.Contains("part 5 (GfxObj 0x01007500): rotation quaternion of length 2 normalised", messages);
        Assert.Contains("CylSphere 0: NaN or infinity", messages);
        Assert.Equal(["part 5 (GfxObj 0x01007500)", "Sphere 0"], query.Shapes.Select(s => s.Name));
        Assert.True(query.Overlaps(new Vector3(5, 0, 1), 0.6f));
        Assert.True(query.Overlaps(new Vector3(9, 9, 0.2f), 0.25f)); // a zero-radius Setup sphere still has the query's own radius
        foreach (var (c, r) in OddProbes) query.Overlaps(c, r);
    }

    private static void RunEverything(CompiledBsp bsp)
    {
        var reference = new BspSphereQuery(bsp);
        var oracle = new BruteForceSphereQuery(bsp);
        foreach (var (c, r) in OddProbes)
        {
            reference.Overlaps(c, r);
            oracle.Overlaps(c, r);
            SurfaceDistance.ToNearestPolygon(bsp, c);
        }
        foreach (var (c, r, _) in StressProbes.For(bsp, 2000, 3))
        {
            reference.Overlaps(c, r);
            oracle.Overlaps(c, r);
        }
    }
}
