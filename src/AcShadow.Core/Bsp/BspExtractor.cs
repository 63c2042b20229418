using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Geometry;

namespace AcShadow.Core.Bsp;

/// <summary>
/// Turns a GfxObj's PhysicsPolygons and PhysicsBSP into a <see cref="BspDump"/>: planes computed the
/// retail way (<see cref="PolygonPlane"/>), only the vertices the physics polygons use, the tree
/// flattened in preorder. Problems (degenerate or non-planar polygons, ids that point nowhere) become
/// diagnostics naming the polygon; they never abort the extraction.
/// </summary>
public static class BspExtractor
{
    /// <summary>Vertices further than this from their polygon's plane make it non-planar (metres).</summary>
    public const float PlanarityTolerance = 1e-4f;

    public static BspDump? Extract(GfxObj gfx)
    {
        if (!gfx.HasPhysics || gfx.PhysicsBsp is null) return null;
        var diagnostics = new List<string>();
        var polygons = new List<BspPolygon>();
        var usedVertices = new SortedSet<int>();
        var degenerate = new List<int>();
        var nonPlanar = new List<int>();

        foreach (var (id, poly) in gfx.PhysicsPolygons.OrderBy(p => p.Key))
        {
            var ids = poly.VertexIds.Select(v => (int)v).ToArray();
            var points = new List<Vector3>(ids.Length);
            var missing = ids.Where(v => v < 0 || !gfx.Vertices.ContainsKey((ushort)v)).ToArray();
            if (missing.Length > 0)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: vertex id(s) {string.Join(", ", missing)} not in the vertex array");
            foreach (var v in ids)
                if (v >= 0 && gfx.Vertices.TryGetValue((ushort)v, out var p)) { points.Add(p); usedVertices.Add(v); }

            Plane? plane = missing.Length == 0 ? PolygonPlane.Compute(points) : null;
            if (ids.Length < 3)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: {ids.Length} vertices, a polygon needs 3");
            if (plane is null)
            {
                degenerate.Add(id);
                if (missing.Length == 0 && ids.Length >= 3)
                    diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: degenerate (collinear or repeated vertices), no plane");
            }
            else
            {
                var deviation = PolygonPlane.MaxDeviation(plane.Value, points);
                if (deviation > PlanarityTolerance)
                {
                    nonPlanar.Add(id);
                    diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: non-planar, a vertex lies {deviation:0.######} m off the plane");
                }
            }
            polygons.Add(new BspPolygon(id, ids, plane, poly.SidesType, poly.Stippling));
        }

        var polygonIds = polygons.Select(p => p.Id).ToHashSet();
        var nodes = new List<BspNode>();
        var maxDepth = 0;
        Flatten(gfx.PhysicsBsp, 0);

        var vertices = usedVertices.Select(v => new BspVertex(v, gfx.Vertices[(ushort)v])).ToArray();
        var leaves = nodes.Where(n => n.IsLeaf).ToArray();
        var stats = new BspStats(vertices.Length, polygons.Count, nodes.Count, leaves.Length, leaves.Count(l => l.Solid), maxDepth, degenerate, nonPlanar);
        return new BspDump(gfx.Id, gfx.PhysicsBsp.BoundingSphere, vertices, polygons, nodes, stats, diagnostics);

        int Flatten(PhysicsBspNode node, int depth)
        {
            maxDepth = Math.Max(maxDepth, depth);
            var index = nodes.Count;
            nodes.Add(null!);
            if (node.IsLeaf)
            {
                var ids = node.Polygons.Select(p => (int)p).ToArray();
                foreach (var p in ids.Where(p => !polygonIds.Contains(p)))
                    diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP leaf {node.LeafIndex}: polygon id {p} is not a physics polygon");
                nodes[index] = new BspNode(index, node.Type, null, node.BoundingSphere, null, null, node.LeafIndex, node.Solid != 0, ids);
                return index;
            }
            int? pos = node.Pos is null ? null : Flatten(node.Pos, depth + 1);
            int? neg = node.Neg is null ? null : Flatten(node.Neg, depth + 1);
            nodes[index] = new BspNode(index, node.Type, node.SplittingPlane, node.BoundingSphere, pos, neg, 0, false, []);
            return index;
        }
    }
}
