using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Chart;
using AcShadow.Tests.Scenes;

namespace AcShadow.Tests.Collision;

/// <summary>
/// The per-radius voxel index of a tree answers exactly as the walk it replaces (<see cref="BspSphereQuery.Overlaps"/>)
/// at every centre: a dense grid, and centres one ulp either side of every decision the walk takes (reach and zero
/// from every node plane, reach from every polygon plane, node-sphere boundaries, voxel boundaries), on every sample
/// tree, the sample's cells, and trees malformed the ways real dats are.
/// </summary>
public class BspReachGridTests
{
    private static readonly float[] IndexedRadii = [0.5f, 0.3f, 1.25f, 0.0001f, 0f];

    [Fact]
    public void Every_sample_tree_answers_as_the_walk_at_every_probe()
    {
        foreach (var dump in CollisionCorpus.Sample)
            AssertAgrees($"GfxObj 0x{dump.GfxObjId:X8}", CompiledBsp.Compile(dump));
    }

    [Fact]
    public void The_sample_cells_answer_as_the_walk_at_every_probe()
    {
        var report = SceneCompileTests.Exact.Value;
        var cells = report.Cells.Where(c => c.Bsp is not null).ToArray();
        Assert.NotEmpty(cells);
        foreach (var cell in cells) AssertAgrees($"cell 0x{cell.Cell.Id:X8}", cell.Bsp!);
    }

    [Fact]
    public void The_test_meshes_answer_as_the_walk_at_every_probe()
    {
        foreach (var (name, dump) in CollisionCorpus.Forged()) AssertAgrees(name, CompiledBsp.Compile(dump));
    }

    [Fact]
    public void The_sample_building_is_mostly_settled_ahead_of_time()
    {
        var building = CompiledBsp.Compile(CollisionCorpus.Sample.Single(d => d.GfxObjId == 0x01005000));
        var grid = BspReachGrid.Build(new BspSphereQuery(building), 0.5f)!;
        var (clear, _, frontier, _) = grid.StateCounts();
        Assert.True(clear > 0, "no clear voxel");
        Assert.True(frontier > 0, "no frontier voxel");
        Assert.True(grid.Bytes < 1 << 20, $"{grid.Bytes} bytes");
        // The building's tree has no solid leaf, so nothing in it is blocked for every centre; a part with solid
        // leaves is blocked deep inside them.
        Assert.Empty(building.SolidCells);
        var part = CompiledBsp.Compile(CollisionCorpus.Sample.Single(d => d.GfxObjId == 0x010044B5));
        Assert.NotEmpty(part.SolidCells);
        Assert.True(BspReachGrid.Build(new BspSphereQuery(part), 0.5f)!.StateCounts().Blocked > 0, "no blocked voxel");
    }

    [Fact]
    public void The_counted_cost_through_the_index_answers_as_the_walk_and_counts_less()
    {
        var report = SceneCompileTests.Exact.Value;
        var grids = new BspReachGrids([0.5f]);
        var door = report.Compiled.Values.Single(c => c.Id == 0x020019FF).Retail!;
        // Indexing the door's parts builds their grids, which the counter then finds.
        var query = Assert.IsType<ObjectOverlapQuery>(door.Query).Indexed(grids);
        var plain = new QueryCost.Counter(door.Shapes);
        var indexed = new QueryCost.Counter(door.Shapes, grids: grids);
        long plainOps = 0, indexedOps = 0;
        foreach (var p in report.Compiled.Values.Single(c => c.Id == 0x020019FF).Probes)
        {
            plainOps += plain.Count(p.Center, p.Radius, out var expected);
            indexedOps += indexed.Count(p.Center, p.Radius, out var answer);
            Assert.Equal(expected, answer);
            Assert.Equal(door.Overlaps(p.Center, p.Radius), answer);
            Assert.Equal(answer, query.Overlaps(p.Center, p.Radius));
        }
        Assert.True(indexedOps < plainOps, $"{indexedOps} counted through the index, {plainOps} walking");
    }

    [Fact]
    public void A_polygon_across_its_split_plane_is_still_found()
    {
        // The wall x = 0.5 spans z = 0..2 but sits in the positive leaf of the split z = 1 only: a sphere below z = 1
        // beside it is sent to the negative side, where the walk does not see the wall, and the index must agree.
        var wall = Quad(0, new(0.5f, -1, 0), new(0.5f, 1, 0), new(0.5f, 1, 2), new(0.5f, -1, 2));
        var floor = Quad(4, new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0));
        var dump = Dump(0x01007A00, [wall, floor],
        [
            Internal(0, new Plane(Vector3.UnitZ, -1f), new(0, 0, 1), 2f, 1, 2),
            Leaf(1, new(0, 0, 1), 2f, solid: false, 0),
            Leaf(2, new(0, 0, 1), 2f, solid: true, 4),
        ]);
        AssertAgrees("wall across its split plane", CompiledBsp.Compile(dump));
    }

    [Fact]
    public void A_node_sphere_too_small_for_its_polygons_is_kept_as_the_walk_keeps_it()
    {
        var floor = Quad(0, new(-2, -2, 0), new(2, -2, 0), new(2, 2, 0), new(-2, 2, 0));
        var dump = Dump(0x01007A01, [floor],
        [
            Internal(0, new Plane(Vector3.UnitZ, 0f), new(0, 0, 0), 3f, 1, 2),
            Leaf(1, new(0.5f, 0.5f, 0), 0.2f, solid: false, 0),
            Leaf(2, new(0, 0, 0), 0.1f, solid: true, 0),
        ]);
        AssertAgrees("node spheres too small", CompiledBsp.Compile(dump));
    }

    [Fact]
    public void A_solid_leaf_without_polygons_blocks_nothing_in_the_index_either()
    {
        var floor = Quad(0, new(-1, -1, 0), new(1, -1, 0), new(1, 1, 0), new(-1, 1, 0));
        var dump = Dump(0x01007A02, [floor],
        [
            Internal(0, new Plane(Vector3.UnitZ, 0f), new(0, 0, 0), 2f, 1, 2),
            Internal(1, new Plane(Vector3.UnitX, 0f), new(0, 0, 0.5f), 2f, 3, 4),
            Leaf(2, new(0, 0, 0), 2f, solid: true),
            Leaf(3, new(0, 0, 0.5f), 2f, solid: false, 0),
            Leaf(4, new(0, 0, 0.5f), 2f, solid: true),
        ]);
        AssertAgrees("solid leaves without polygons", CompiledBsp.Compile(dump));
    }

    /// <summary>
    /// For each indexed radius: the index answers as the walk at every probe, through <see cref="IndexedBspQuery"/>
    /// too, and radii it was not built for walk the tree with the same answers.
    /// </summary>
    private static void AssertAgrees(string name, CompiledBsp bsp)
    {
        var walk = new BspSphereQuery(bsp);
        var grids = IndexedRadii.Select(r => BspReachGrid.Build(walk, r)).Where(g => g is not null).Select(g => g!).ToArray();
        if (bsp.Nodes.Length > 0 && float.IsFinite(bsp.Nodes[0].SphereRadius)) Assert.Equal(IndexedRadii.Length, grids.Length);
        var indexed = new IndexedBspQuery(walk, grids);
        foreach (var grid in grids)
        {
            var r = grid.Radius;
            foreach (var c in Probes(bsp, grid))
            {
                var expected = walk.Overlaps(c, r);
                if (grid.Overlaps(c) != expected || indexed.Overlaps(c, r) != expected)
                    Assert.Fail($"{name}, radius {r}: the index answers {!expected} at ({c.X:R}, {c.Y:R}, {c.Z:R}), the walk {expected}");
            }
        }
        foreach (var r in new[] { 0.7f, 0.49999997f, float.NaN, -1f })
            foreach (var c in Probes(bsp, grids.FirstOrDefault()).Take(4000))
                Assert.Equal(walk.Overlaps(c, r), indexed.Overlaps(c, r));
    }

    /// <summary>A dense grid over the index's box and centres an ulp either side of each of the walk's decisions.</summary>
    private static IEnumerable<Vector3> Probes(CompiledBsp bsp, BspReachGrid? grid)
    {
        var r = grid?.Radius ?? 0.5f;
        var reach = r - PhysicsEpsilon.Value;
        var nodes = bsp.Nodes;
        var rootCenter = nodes.Length > 0 && float.IsFinite(nodes[0].SphereRadius) ? nodes[0].SphereCenter : Vector3.Zero;
        var rootRadius = nodes.Length > 0 && float.IsFinite(nodes[0].SphereRadius) ? nodes[0].SphereRadius : 2f;
        var half = rootRadius + r + 0.1f;
        const int Steps = 36;
        for (var i = 0; i <= Steps; i++)
            for (var j = 0; j <= Steps; j++)
                for (var k = 0; k <= Steps; k++)
                    yield return rootCenter + new Vector3(-half + 2 * half * i / Steps, -half + 2 * half * j / Steps, -half + 2 * half * k / Steps);
        yield return rootCenter;
        yield return rootCenter + new Vector3(1e4f, 0, 0);
        yield return rootCenter - new Vector3(0, 0, half * 3);
        foreach (var node in nodes)
        {
            var sphere = node.SphereRadius + r;
            if (float.IsFinite(sphere))
                foreach (var d in Directions)
                    foreach (var c in Ulps(node.SphereCenter + d * sphere)) yield return c;
            if (node.IsLeaf) continue;
            var onPlane = node.SphereCenter - node.Normal * (Vector3.Dot(node.Normal, node.SphereCenter) + node.D);
            foreach (var t in new[] { reach, -reach, 0f })
                foreach (var d in Directions)
                    foreach (var c in Ulps(onPlane + node.Normal * t + Vector3.Normalize(d - node.Normal * Vector3.Dot(d, node.Normal) + new Vector3(1e-3f)) * rootRadius * 0.3f))
                        yield return c;
        }
        foreach (var polygon in bsp.Polygons)
        {
            var centre = polygon.Vertices.Aggregate(Vector3.Zero, (a, v) => a + v) / polygon.Vertices.Length;
            foreach (var p in polygon.Vertices.Append(centre))
                foreach (var t in new[] { reach, -reach, r, -r })
                    foreach (var c in Ulps(p + polygon.Normal * t)) yield return c;
        }
        if (grid is null) yield break;
        // Voxel boundaries: centres on and beside the planes that split voxels.
        var edge = 1f / grid.InverseVoxelEdge;
        var random = new Random(11);
        for (var n = 0; n < 400; n++)
        {
            var corner = grid.Origin + new Vector3(random.Next(0, 128), random.Next(0, 128), random.Next(0, 128)) * edge;
            foreach (var c in Ulps(corner)) yield return c;
        }
    }

    private static readonly Vector3[] Directions =
        [Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitZ, Vector3.Normalize(new(1, 1, 1)), Vector3.Normalize(new(-1, 2, -0.5f))];

    /// <summary>A point and its neighbours one ulp away along each axis, and a micrometre away.</summary>
    private static IEnumerable<Vector3> Ulps(Vector3 p)
    {
        yield return p;
        yield return new(MathF.BitIncrement(p.X), p.Y, p.Z);
        yield return new(MathF.BitDecrement(p.X), p.Y, p.Z);
        yield return new(p.X, MathF.BitIncrement(p.Y), p.Z);
        yield return new(p.X, MathF.BitDecrement(p.Y), p.Z);
        yield return new(p.X, p.Y, MathF.BitIncrement(p.Z));
        yield return new(p.X, p.Y, MathF.BitDecrement(p.Z));
        yield return new(MathF.BitIncrement(p.X), MathF.BitIncrement(p.Y), MathF.BitIncrement(p.Z));
        yield return new(MathF.BitDecrement(p.X), MathF.BitDecrement(p.Y), MathF.BitDecrement(p.Z));
        yield return p + new Vector3(1e-6f);
        yield return p - new Vector3(1e-6f);
    }

    private static (BspPolygon Polygon, BspVertex[] Vertices) Quad(int firstVertex, params Vector3[] corners)
    {
        var vertices = corners.Select((v, i) => new BspVertex(firstVertex + i, v)).ToArray();
        var plane = PolygonPlane.Compute(corners);
        return (new BspPolygon(firstVertex, [.. vertices.Select(v => v.Id)], plane, SidesType.Clockwise, Stippling.NoPos), vertices);
    }

    private static BspNode Internal(int index, Plane plane, Vector3 center, float radius, int pos, int neg) =>
        new(index, BspNodeType.BPIN, plane, new Sphere(center, radius), pos, neg, 0, false, []);

    private static BspNode Leaf(int index, Vector3 center, float radius, bool solid, params int[] polygons) =>
        new(index, BspNodeType.Leaf, null, new Sphere(center, radius), null, null, index, solid, polygons);

    private static BspDump Dump(uint id, (BspPolygon Polygon, BspVertex[] Vertices)[] polygons, BspNode[] nodes) =>
        new(id, new Sphere(nodes[0].Sphere.Center, nodes[0].Sphere.Radius), [.. polygons.SelectMany(p => p.Vertices)], [.. polygons.Select(p => p.Polygon)], nodes,
            new BspStats(polygons.Sum(p => p.Vertices.Length), polygons.Length, nodes.Length, nodes.Count(n => n.Type == BspNodeType.Leaf), 0, 0, [], []), []);
}
