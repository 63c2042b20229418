using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Geometry;

namespace AcShadow.Core.Bsp;

/// <summary>
/// Turns a GfxObj's PhysicsPolygons and PhysicsBSP into a <see cref="BspDump"/>: planes computed the
/// retail way (<see cref="PolygonPlane"/>), only the vertices the physics polygons use, the tree
/// flattened in preorder. Problems (degenerate or non-planar polygons, ids that point nowhere, NaN or
/// infinite coordinates, a tree deeper than <see cref="BspLimits.MaxDepth"/>) become diagnostics naming
/// the polygon or node; they never abort the extraction. A vertex that is not finite is left out like a
/// missing one (its polygons get no plane), an internal node's non-finite splitting plane is written as
/// absent, and nodes below the depth limit are dropped, so the dump holds only what a consumer can use.
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

        var nonFinite = gfx.Vertices.Where(kv => !IsFinite(kv.Value)).Select(kv => (int)kv.Key).Order().ToArray();
        if (nonFinite.Length > 0)
            diagnostics.Add($"GfxObj 0x{gfx.Id:X8}: vertex id(s) {string.Join(", ", nonFinite)} have NaN or infinite coordinates; left out, so polygons using them get no plane");
        var unusable = nonFinite.ToHashSet();

        foreach (var (id, poly) in gfx.PhysicsPolygons.OrderBy(p => p.Key))
        {
            var ids = poly.VertexIds.Select(v => (int)v).ToArray();
            var points = new List<Vector3>(ids.Length);
            var absent = ids.Where(v => !gfx.Vertices.ContainsKey((ushort)v)).ToArray();
            if (absent.Length > 0)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: vertex id(s) {string.Join(", ", absent)} not in the vertex array");
            var missing = ids.Where(v => !gfx.Vertices.ContainsKey((ushort)v) || unusable.Contains(v)).ToArray();
            foreach (var v in ids)
                if (!unusable.Contains(v) && gfx.Vertices.TryGetValue((ushort)v, out var p)) { points.Add(p); usedVertices.Add(v); }

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
        var droppedBelowLimit = 0;
        Flatten(gfx.PhysicsBsp, 0);
        if (droppedBelowLimit > 0)
            diagnostics.Add($"GfxObj 0x{gfx.Id:X8}: the PhysicsBSP is deeper than {BspLimits.MaxDepth} levels, which no real one is; {droppedBelowLimit} subtree(s) below that depth are dropped");

        var vertices = usedVertices.Select(v => new BspVertex(v, gfx.Vertices[(ushort)v])).ToArray();
        var leaves = nodes.Where(n => n.IsLeaf).ToArray();
        var stats = new BspStats(vertices.Length, polygons.Count, nodes.Count, leaves.Length, leaves.Count(l => l.Solid), maxDepth, degenerate, nonPlanar);
        return new BspDump(gfx.Id, gfx.PhysicsBsp.BoundingSphere, vertices, polygons, nodes, stats, diagnostics);

        int? Flatten(PhysicsBspNode node, int depth)
        {
            if (depth > BspLimits.MaxDepth)
            {
                droppedBelowLimit++;
                return null;
            }
            maxDepth = Math.Max(maxDepth, depth);
            var index = nodes.Count;
            nodes.Add(null!);
            if (!IsFinite(node.BoundingSphere.Center) || !float.IsFinite(node.BoundingSphere.Radius))
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP node {index}: bounding sphere has NaN or infinite values");
            if (node.IsLeaf)
            {
                var ids = node.Polygons.Select(p => (int)p).ToArray();
                foreach (var p in ids.Where(p => !polygonIds.Contains(p)))
                    diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP leaf {node.LeafIndex}: polygon id {p} is not a physics polygon");
                nodes[index] = new BspNode(index, node.Type, null, node.BoundingSphere, null, null, node.LeafIndex, node.Solid != 0, ids);
                return index;
            }
            Plane? splitting = node.SplittingPlane;
            if (!IsFinite(node.SplittingPlane.Normal) || !float.IsFinite(node.SplittingPlane.D))
            {
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP node {index}: splitting plane has NaN or infinite values; written as absent");
                splitting = null;
            }
            var pos = node.Pos is null ? null : Flatten(node.Pos, depth + 1);
            var neg = node.Neg is null ? null : Flatten(node.Neg, depth + 1);
            nodes[index] = new BspNode(index, node.Type, splitting, node.BoundingSphere, pos, neg, 0, false, []);
            return index;
        }
    }

    private static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
