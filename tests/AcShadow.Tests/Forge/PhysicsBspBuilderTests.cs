using AcShadow.Forge;
using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Forging.Bsp;
using AcShadow.Forging.Geometry;
using AcShadow.Forging.Spec;

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
    public void A_300_polygon_part_builds_with_a_bounded_depth_and_sound_invariants()
    {
        var m = new MeshBuilder().Box(new(-2, -2, 0), new(2, 2, 4), 7, 7, 7); // 294 quads
        m.Prism(new(0, 0, 4), 1, 1, 6);                                          // + 8
        // How long this takes is measured by tools/AcShadow.Bench (ForgeBspBenchmarks), not asserted here.
        var gfx = Gfx(m);
        Assert.True(gfx.PhysicsPolygons.Count >= 300);
        Assert.Empty(BspInvariants.Check(gfx));
        Assert.InRange(BspInvariants.Depth(gfx.PhysicsBsp!), 2, PhysicsBspBuilder.MaxDepth);
    }

    [Fact]
    public void Building_is_deterministic()
    {
        var (vertices, polygons) = Mesh(new MeshBuilder().Box(new(0, 0, 0), new(3, 2, 1), 3, 2, 1).Prism(new(5, 0, 0), 1, 2, 12, 3));
        var a = new Core.Dat.Binary.DatBinaryWriter();
        var b = new Core.Dat.Binary.DatBinaryWriter();
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
    public void Solid_leaves_hold_polygons_and_appear_only_in_closed_meshes()
    {
        var (_, box) = Mesh(new MeshBuilder().Box(Vector3.Zero, Vector3.One));
        var (_, quad) = Mesh(new MeshBuilder().Polygon([new(0, 0, 0), new(1, 0, 0), new(1, 1, 0)]));
        Assert.True(PhysicsBspBuilder.IsClosed(box));
        Assert.False(PhysicsBspBuilder.IsClosed(quad));

        var closed = Gfx(new MeshBuilder().Box(new(0, 0, 0), new(3, 1, 1), 3, 1, 1));
        var leaves = BspInvariants.Leaves(closed.PhysicsBsp!).ToArray();
        Assert.Contains(leaves, l => l.Solid != 0);
        Assert.All(leaves.Where(l => l.Solid != 0), l => Assert.NotEmpty(l.Polygons));
        // Empty sides are leaves too (every internal node has both children), never solid.
        Assert.Contains(leaves, l => l.Polygons.Count == 0);
        Assert.All(leaves.Where(l => l.Polygons.Count == 0), l => Assert.Equal(0, l.Solid));

        var open = Gfx(new MeshBuilder().Grid((i, j) => new(i, j, 0), 6, 6).Grid((i, k) => new(i, 3, k), 6, 2));
        Assert.DoesNotContain(BspInvariants.Leaves(open.PhysicsBsp!), l => l.Solid != 0);
    }

    [Fact]
    public void Every_solid_leaf_holds_polygons_and_no_empty_leaf_is_solid()
    {
        // Over every physics GfxObj of the sample and a small scale spec: closed meshes have solid leaves,
        // all of them holding polygons (retail's centre check runs only at a leaf with NumPolys != 0);
        // open meshes (the jamb's one-sided threshold, the house's two-sided walls) have none.
        var spec = SpecValidator.Validate(SampleDats.Spec).GfxObjs
            .Concat(SpecValidator.Validate(ScaleSpecGenerator.Generate(60, 3)).GfxObjs)
            .Where(g => g.Physics).ToArray();
        int closedCount = 0, solidCount = 0;
        foreach (var g in spec)
        {
            var gfx = SpecCompiler.ToGfxObj(g);
            var leaves = BspInvariants.Leaves(gfx.PhysicsBsp!).ToArray();
            Assert.DoesNotContain(leaves, l => l.Solid != 0 && l.Polygons.Count == 0);
            var solid = leaves.Count(l => l.Solid != 0);
            if (PhysicsBspBuilder.IsClosed(g.Polygons.Select(p => p.VertexIds).ToArray()))
            {
                closedCount++;
                Assert.True(solid > 0, $"0x{g.Id:X8}: a closed mesh without a solid leaf");
                solidCount += solid;
            }
            else Assert.True(solid == 0, $"0x{g.Id:X8}: an open mesh with {solid} solid leaves");
        }
        Assert.True(closedCount > 20 && solidCount >= closedCount, $"{closedCount} closed meshes, {solidCount} solid leaves");
        foreach (var id in new[] { SampleSpecAuthor.DoorJamb, SampleSpecAuthor.House })
            Assert.False(PhysicsBspBuilder.IsClosed(spec.Single(g => g.Id == id).Polygons.Select(p => p.VertexIds).ToArray()));
    }

    [Fact]
    public void A_polygon_in_the_splitting_plane_goes_behind_it_to_the_solid_it_bounds()
    {
        // A box on a floor (the box's bottom faces down, the floor up, both in z = 0) and a wall built of
        // two opposite faces: a polygon lying in a node's plane sits below the node only on the side behind
        // it — negative when it faces the way the plane does, positive when it faces the other way.
        var m = new MeshBuilder().Grid((i, j) => new(i - 2, j - 2, 0), 4, 4).Box(new(-0.5f, -0.5f, 0), new(0.5f, 0.5f, 1))
            .Polygon([new(-2, 1.5f, 0), new(2, 1.5f, 0), new(2, 1.5f, 2), new(-2, 1.5f, 2)])
            .Polygon([new(-2, 1.5f, 2), new(2, 1.5f, 2), new(2, 1.5f, 0), new(-2, 1.5f, 0)]);
        var gfx = Gfx(m);
        Assert.Empty(BspInvariants.Check(gfx));
        var samples = SpecValidator.Validate(SampleDats.Spec).GfxObjs.Where(g => g.Physics).Select(SpecCompiler.ToGfxObj);
        int same = 0, opposite = 0;
        foreach (var g in samples.Append(gfx))
        {
            var planes = g.PhysicsPolygons.ToDictionary(p => p.Key, p => p.Value.VertexIds.Select(v => g.Vertices[(ushort)v]).ToArray());
            void Walk(PhysicsBspNode n)
            {
                if (n.IsLeaf) return;
                var pos = n.Pos is null ? [] : BspInvariants.Leaves(n.Pos).SelectMany(l => l.Polygons).ToHashSet();
                var neg = n.Neg is null ? [] : BspInvariants.Leaves(n.Neg).SelectMany(l => l.Polygons).ToHashSet();
                foreach (var id in pos.Union(neg))
                {
                    var points = planes[id];
                    if (points.Any(p => MathF.Abs(PolygonPlane.Distance(n.SplittingPlane, p)) > PhysicsBspBuilder.OnPlaneEpsilon)) continue;
                    var own = PolygonPlane.Compute(points);
                    if (own is null) continue;
                    if (PolygonPlane.Dot(own.Value.Normal, n.SplittingPlane.Normal) > 0)
                    {
                        same++;
                        Assert.Contains(id, neg);
                        // Only a solid leaf standing for inside in front of the plane lists it there too.
                        if (pos.Contains(id)) Assert.True(n.Pos is { IsLeaf: true, Solid: not 0 }, $"0x{g.Id:X8}: polygon {id} in front of its own plane");
                    }
                    else
                    {
                        opposite++;
                        Assert.Contains(id, pos);
                        Assert.DoesNotContain(id, neg);
                    }
                }
                if (n.Pos is not null) Walk(n.Pos);
                if (n.Neg is not null) Walk(n.Neg);
            }
            Walk(g.PhysicsBsp!);
        }
        Assert.True(same > 50 && opposite > 5, $"{same} same-facing, {opposite} opposite-facing polygons in a node's plane");
    }

    /// <summary>The leaf a point falls into (positive when in front or on the plane, as retail's centre check goes), or null when that child is absent.</summary>
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

    /// <summary>A slab on four legs pushed 0.1 m into it: two closed pieces, one inside the other near the joins.</summary>
    private static MeshBuilder SlabOnLegs()
    {
        var m = new MeshBuilder().Box(new(0, 0, 0.8f), new(2, 1, 1));
        foreach (var (x, y) in new[] { (0.1f, 0.1f), (1.7f, 0.1f), (0.1f, 0.7f), (1.7f, 0.7f) })
            m.Box(new(x, y, 0), new(x + 0.2f, y + 0.2f, 0.9f));
        return m;
    }

    /// <summary>Four overlapping boxes (found by a seeded search): one of its splits leaves nothing in front of a plane that is still inside another box.</summary>
    private static readonly (Vector3 Min, Vector3 Max)[] OverlappingBoxes =
    [
        (new(0.5f, 0.25f, 0.5f), new(1.5f, 1.25f, 1.25f)),
        (new(0f, 0.5f, 0.75f), new(0.75f, 1f, 1f)),
        (new(0.25f, 0.5f, 1f), new(1f, 1.25f, 1.5f)),
        (new(0f, 0f, 0.75f), new(0.75f, 0.75f, 1.75f)),
    ];

    private static MeshBuilder Boxes((Vector3 Min, Vector3 Max)[] boxes)
    {
        var m = new MeshBuilder();
        foreach (var (min, max) in boxes) m.Box(min, max);
        return m;
    }

    [Theory]
    [InlineData("box")]
    [InlineData("L")]
    [InlineData("prism")]
    [InlineData("legs")]
    [InlineData("boxes")]
    public void A_point_lands_in_a_solid_leaf_holding_polygons_exactly_when_it_is_inside_the_closed_mesh(string shape)
    {
        // Inside tests written independently of the BSP.
        Vector2[] l = [new(0, 0), new(1, 0), new(1, 0.4f), new(0.4f, 0.4f), new(0.4f, 1), new(0, 1)];
        (MeshBuilder Mesh, Func<Vector3, bool> Inside) c = shape switch
        {
            "box" => (new MeshBuilder().Box(new(-1, -0.5f, 0), new(1, 0.5f, 2), 2, 1, 2),
                p => p.X is > -1 and < 1 && p.Y is > -0.5f and < 0.5f && p.Z is > 0 and < 2),
            "L" => (new MeshBuilder().Box(new(0, 0, 0), new(1, 0.4f, 0.6f)), _ => false), // replaced below
            "legs" => (SlabOnLegs(), p => p.X is > 0 and < 2 && p.Y is > 0 and < 1 && p.Z is > 0.8f and < 1
                || p.Z is > 0 and < 0.9f && (p.X is > 0.1f and < 0.3f || p.X is > 1.7f and < 1.9f) && (p.Y is > 0.1f and < 0.3f || p.Y is > 0.7f and < 0.9f)),
            "boxes" => (Boxes(OverlappingBoxes), p => OverlappingBoxes.Any(b => p.X > b.Min.X && p.X < b.Max.X && p.Y > b.Min.Y && p.Y < b.Max.Y && p.Z > b.Min.Z && p.Z < b.Max.Z)),
            _ => (new MeshBuilder().Prism(Vector3.Zero, 1, 1, 16), p => p.Z is > 0 and < 1 && new Vector2(p.X, p.Y).Length() < MathF.Cos(MathF.PI / 16)),
        };
        GfxObj gfx;
        if (shape == "L")
        {
            gfx = SpecCompiler.ToGfxObj(SpecValidator.Validate(SampleDats.Spec).GfxObjs.Single(g => g.Id == SampleSpecAuthor.LBlock));
            c.Inside = p => p.Z is > 0 and < 0.6f && p.X is > 0 and < 1 && p.Y is > 0 and < 1 && (p.Y < 0.4f || p.X < 0.4f);
        }
        else gfx = Gfx(c.Mesh);
        Assert.Empty(BspInvariants.Check(gfx));

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
            // What retail's centre check sees: a solid leaf that lists polygons (an empty one would be clear).
            var solid = leaf is { Solid: not 0, Polygons.Count: > 0 };
            Assert.True(c.Inside(p) == solid, $"{shape}: point {p} inside={c.Inside(p)} but solid leaf holding polygons={solid}");
            if (solid) inside++; else outside++;
        }
        Assert.True(inside > 50 && outside > 50, $"{inside} inside, {outside} outside");
    }

    [Fact]
    public void Inside_in_front_of_a_splitter_with_nothing_there_still_gets_a_solid_leaf()
    {
        // Where closed pieces overlap, a face of one can lie inside another: a split by its plane can leave
        // no polygon in front, yet in front is inside the other piece. That leaf lists the polygons in the
        // splitting plane (they stay behind it too) and is solid, so a point there is not left in an absent
        // child (the point test above checks the whole of this mesh).
        var gfx = Gfx(Boxes(OverlappingBoxes));
        var polygons = gfx.PhysicsPolygons.ToDictionary(p => p.Key, p => p.Value);
        var found = 0;
        void Walk(PhysicsBspNode n)
        {
            if (n.IsLeaf) return;
            if (n.Pos is { IsLeaf: true, Solid: not 0 } leaf && leaf.Polygons.All(id =>
                    polygons[id].VertexIds.All(v => MathF.Abs(PolygonPlane.Distance(n.SplittingPlane, gfx.Vertices[(ushort)v])) <= PhysicsBspBuilder.OnPlaneEpsilon)))
            {
                found++;
                Assert.True(n.Neg is not null && leaf.Polygons.All(id => BspInvariants.Leaves(n.Neg).Any(l => l.Polygons.Contains(id))));
            }
            if (n.Pos is not null) Walk(n.Pos);
            if (n.Neg is not null) Walk(n.Neg);
        }
        Walk(gfx.PhysicsBsp!);
        Assert.True(found > 0);
    }

    [Fact]
    public void The_reference_blocks_a_small_sphere_wholly_inside_a_closed_part_without_touching_a_face()
    {
        // The door leaf (1.93 x 0.26 x 2.2 m) and the L-block as the sample forges them: retail's centre
        // check fires in a solid leaf, so a 1 cm sphere in the middle blocks though it touches no polygon.
        var (portal, _) = SampleDats.Build();
        using var dat = DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat");
        foreach (var (id, centre) in new[] { (SampleSpecAuthor.DoorLeaf, new Vector3(0.2f, 0, 1.1f)), (SampleSpecAuthor.LBlock, new Vector3(0.2f, 0.7f, 0.3f)) })
        {
            var bsp = CompiledBsp.Compile(BspExtractor.Extract(dat.ReadGfxObj(id)!)!);
            Assert.DoesNotContain(bsp.Polygons, p => PolygonSphereTest.Touches(p, centre, 0.01f));
            Assert.True(new BspSphereQuery(bsp).Overlaps(centre, 0.01f), $"0x{id:X8}");
            Assert.True(new BruteForceSphereQuery(bsp).Overlaps(centre, 0.01f), $"0x{id:X8}");
        }
    }

    [Fact]
    public void No_sample_tree_has_an_inert_solid_leaf()
    {
        var (portal, _) = SampleDats.Build();
        using var dat = DatDatabase.Open(new MemoryStream(portal), "sample_portal.dat");
        var trees = dat.ListIds(DatObjectKind.GfxObj).Select(id => BspExtractor.Extract(dat.ReadGfxObj(id)!)).OfType<AcShadow.Fixtures.Bsp.BspDump>()
            .Select(CompiledBsp.Compile).ToArray();
        Assert.True(trees.Length >= 10);
        Assert.DoesNotContain(trees.SelectMany(t => t.Diagnostics), d => d.Code == CollisionDiagnosticCodes.InertSolidLeaf);
        Assert.True(trees.Count(t => t.SolidCells.Count > 0) >= 5);
    }
}
