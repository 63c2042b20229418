using System.Diagnostics;
using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Geometry;
using AcShadow.Forge;
using AcShadow.Forge.Bsp;
using AcShadow.Forge.Geometry;
using AcShadow.Forge.Spec;

namespace AcShadow.Tests.Forge;

public sealed class PhysicsBspBuilderTests
{
    private static (Vector3[] Vertices, IReadOnlyList<short>[] Polygons) Mesh(MeshBuilder m)
    {
        var spec = m.ToSpec(0x01000001, true, false);
        return (spec.Vertices.Select(v => new Vector3((float)v![0], (float)v[1], (float)v[2])).ToArray(),
            spec.Polygons.Select(p => (IReadOnlyList<short>)p.Vertices.Select(v => (short)v).ToArray()).ToArray());
    }

    private static GfxObj Gfx(MeshBuilder m) =>
        SpecCompiler.ToGfxObj(SpecValidator.Validate(new ForgeSpec { GfxObjs = [m.ToSpec(0x01000001, true, false)] }).GfxObjs[0]);

    [Fact]
    public void A_300_polygon_part_builds_fast_with_a_bounded_depth_and_sound_invariants()
    {
        var m = new MeshBuilder().Box(new(-2, -2, 0), new(2, 2, 4), 7, 7, 7); // 294 quads
        m.Prism(new(0, 0, 4), 1, 1, 6);                                          // + 8
        var stopwatch = Stopwatch.StartNew();
        var gfx = Gfx(m);
        stopwatch.Stop();
        Assert.True(gfx.PhysicsPolygons.Count >= 300);
        Assert.True(stopwatch.ElapsedMilliseconds < 2000, $"{stopwatch.ElapsedMilliseconds} ms");
        Assert.Empty(BspInvariants.Check(gfx));
        Assert.InRange(BspInvariants.Depth(gfx.PhysicsBsp!), 2, PhysicsBspBuilder.MaxDepth);
    }

    [Fact]
    public void Building_is_deterministic()
    {
        var (vertices, polygons) = Mesh(new MeshBuilder().Box(new(0, 0, 0), new(3, 2, 1), 3, 2, 1).Prism(new(5, 0, 0), 1, 2, 12, 3));
        var a = new Core.Dat.DatBinaryWriter();
        var b = new Core.Dat.DatBinaryWriter();
        PhysicsBspBuilder.Build(vertices, polygons).Write(a);
        PhysicsBspBuilder.Build(vertices, polygons).Write(b);
        Assert.Equal(a.ToArray(), b.ToArray());
    }

    [Fact]
    public void Degenerate_polygons_never_split_and_do_not_crash_the_builder()
    {
        Vector3[] vertices = [new(0, 0, 0), new(1, 0, 0), new(2, 0, 0), new(3, 0, 0), new(0, 0, 0)];
        IReadOnlyList<short>[] polygons = [[0, 1, 2], [1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 4, 1], [2, 3, 1]];
        var root = PhysicsBspBuilder.Build(vertices, polygons);
        Assert.True(root.IsLeaf);
        Assert.Equal([0, 1, 2, 3, 4, 5], root.Polygons.Select(p => (int)p));
        Assert.True(root.BoundingSphere.Radius >= 1.5f);
    }

    [Fact]
    public void Spanning_polygons_go_to_both_sides_and_are_never_cut()
    {
        // Two crossing walls: each spans the other's plane.
        var m = new MeshBuilder()
            .Polygon([new(-1, 0, 0), new(1, 0, 0), new(1, 0, 1), new(-1, 0, 1)])
            .Polygon([new(0, -1, 0), new(0, 1, 0), new(0, 1, 1), new(0, -1, 1)]);
        for (var i = 0; i < 4; i++) m.Polygon([new(5 + i, 5, 0), new(6 + i, 5, 0), new(6 + i, 6, 0)]);
        var gfx = Gfx(m);
        Assert.Empty(BspInvariants.Check(gfx));
        var leaves = BspInvariants.Leaves(gfx.PhysicsBsp!).ToArray();
        Assert.All(leaves.SelectMany(l => l.Polygons), id => Assert.InRange(id, 0, 5));
    }

    [Fact]
    public void Internal_planes_are_bitwise_retail_polygon_planes()
    {
        var m = new MeshBuilder().Prism(new(0.3f, -0.2f, 0.1f), 0.77f, 1.3f, 11, 2);
        var gfx = Gfx(m);
        var planes = gfx.PhysicsPolygons.Select(p => PolygonPlane.Compute(p.Value.VertexIds.Select(v => gfx.Vertices[(ushort)v]).ToArray())!.Value).ToHashSet();
        var internals = new List<PhysicsBspNode>();
        void Walk(PhysicsBspNode n) { if (n.IsLeaf) return; internals.Add(n); if (n.Pos is not null) Walk(n.Pos); if (n.Neg is not null) Walk(n.Neg); }
        Walk(gfx.PhysicsBsp!);
        Assert.NotEmpty(internals);
        Assert.All(internals, n => Assert.Contains(n.SplittingPlane, planes));
    }

    [Fact]
    public void Solid_leaves_are_empty_and_appear_only_in_closed_meshes()
    {
        var (_, box) = Mesh(new MeshBuilder().Box(Vector3.Zero, Vector3.One));
        var (_, quad) = Mesh(new MeshBuilder().Polygon([new(0, 0, 0), new(1, 0, 0), new(1, 1, 0)]));
        Assert.True(PhysicsBspBuilder.IsClosed(box));
        Assert.False(PhysicsBspBuilder.IsClosed(quad));

        var closed = Gfx(new MeshBuilder().Box(new(0, 0, 0), new(3, 1, 1), 3, 1, 1));
        var solids = BspInvariants.Leaves(closed.PhysicsBsp!).Where(l => l.Solid != 0).ToArray();
        Assert.NotEmpty(solids);
        Assert.All(solids, l => Assert.Empty(l.Polygons));

        var open = Gfx(new MeshBuilder().Grid((i, j) => new(i, j, 0), 6, 6).Grid((i, k) => new(i, 3, k), 6, 2));
        Assert.DoesNotContain(BspInvariants.Leaves(open.PhysicsBsp!), l => l.Solid != 0);
    }

    /// <summary>The leaf a point falls into (pos when in front or on the plane), or null when that child is absent.</summary>
    private static PhysicsBspNode? Locate(PhysicsBspNode node, Vector3 p)
    {
        while (!node.IsLeaf)
        {
            var next = PolygonPlane.Distance(node.SplittingPlane, p) >= 0 ? node.Pos : node.Neg;
            if (next is null) return null;
            node = next;
        }
        return node;
    }

    [Theory]
    [InlineData("box")]
    [InlineData("L")]
    [InlineData("prism")]
    public void A_point_lands_in_a_solid_leaf_exactly_when_it_is_inside_the_closed_mesh(string shape)
    {
        // Inside tests written independently of the BSP.
        Vector2[] l = [new(0, 0), new(1, 0), new(1, 0.4f), new(0.4f, 0.4f), new(0.4f, 1), new(0, 1)];
        (MeshBuilder Mesh, Func<Vector3, bool> Inside) c = shape switch
        {
            "box" => (new MeshBuilder().Box(new(-1, -0.5f, 0), new(1, 0.5f, 2), 2, 1, 2),
                p => p.X is > -1 and < 1 && p.Y is > -0.5f and < 0.5f && p.Z is > 0 and < 2),
            "L" => (new MeshBuilder().Box(new(0, 0, 0), new(1, 0.4f, 0.6f)), _ => false), // replaced below
            _ => (new MeshBuilder().Prism(Vector3.Zero, 1, 1, 16), p => p.Z is > 0 and < 1 && new Vector2(p.X, p.Y).Length() < MathF.Cos(MathF.PI / 16)),
        };
        GfxObj gfx;
        if (shape == "L")
        {
            gfx = SpecCompiler.ToGfxObj(SpecValidator.Validate(SampleDats.Spec).GfxObjs.Single(g => g.Id == SampleSpecAuthor.LBlock));
            c.Inside = p => p.Z is > 0 and < 0.6f && p.X is > 0 and < 1 && p.Y is > 0 and < 1 && (p.Y < 0.4f || p.X < 0.4f);
        }
        else gfx = Gfx(c.Mesh);

        var random = new Random(5);
        var min = gfx.Vertices.Values.Aggregate(Vector3.Min) - new Vector3(0.3f);
        var size = gfx.Vertices.Values.Aggregate(Vector3.Max) + new Vector3(0.3f) - min;
        int inside = 0, outside = 0;
        for (var i = 0; i < 4000; i++)
        {
            var p = min + size * new Vector3((float)random.NextDouble(), (float)random.NextDouble(), (float)random.NextDouble());
            // Skip points too close to a surface for the simple inside test to be exact.
            if (gfx.PhysicsPolygons.Any(kv => MathF.Abs(PolygonPlane.Distance(PolygonPlane.Compute(kv.Value.VertexIds.Select(v => gfx.Vertices[(ushort)v]).ToArray())!.Value, p)) < 0.01f)) continue;
            var leaf = Locate(gfx.PhysicsBsp!, p);
            var solid = leaf is { Solid: not 0 };
            Assert.True(c.Inside(p) == solid, $"{shape}: point {p} inside={c.Inside(p)} but solid leaf={solid}");
            if (solid) inside++; else outside++;
        }
        Assert.True(inside > 50 && outside > 50, $"{inside} inside, {outside} outside");
    }

    [Fact]
    public void An_empty_solid_leaf_takes_its_parents_sphere()
    {
        // A closed L-prism: some split of it leaves nothing behind the plane.
        var gfx = SpecCompiler.ToGfxObj(SpecValidator.Validate(SampleDats.Spec).GfxObjs.Single(g => g.Id == SampleSpecAuthor.LBlock));
        var solids = new List<(PhysicsBspNode Parent, PhysicsBspNode Leaf)>();
        void Walk(PhysicsBspNode n)
        {
            if (n.IsLeaf) return;
            foreach (var c in new[] { n.Pos, n.Neg })
                if (c is not null) { if (c.IsLeaf && c.Solid != 0) solids.Add((n, c)); Walk(c); }
        }
        Walk(gfx.PhysicsBsp!);
        Assert.All(solids, s =>
        {
            Assert.Same(s.Parent.Neg, s.Leaf);
            Assert.Equal(s.Parent.BoundingSphere, s.Leaf.BoundingSphere);
        });
    }
}
