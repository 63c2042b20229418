using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Bsp;

/// <summary>
/// Turns a GfxObj's PhysicsPolygons and PhysicsBSP into a <see cref="BspDump"/>: planes computed the
/// retail way (<see cref="PolygonPlane"/>), only the vertices the physics polygons use, the tree
/// flattened in preorder. Problems (degenerate or non-planar polygons, ids that point nowhere, NaN or
/// infinite coordinates, a tree deeper than <see cref="BspLimits.MaxDepth"/>, an internal node with one
/// child) become diagnostics naming
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
        var polygons = new List<BspPolygon>(gfx.PhysicsPolygons.Count);
        // Sized for every polygon's vertex ids at once: grown by doubling it was 14 of a batch's 52 MB of int arrays.
        var vertexRefs = 0;
        foreach (var (_, poly) in gfx.PhysicsPolygons) vertexRefs += poly.VertexIds.Count;
        var usedVertices = new List<int>(vertexRefs);
        var degenerate = new List<int>();
        var nonPlanar = new List<int>();

        var unusable = NonFiniteVertices(gfx.Vertices);
        if (unusable.Count > 0)
            diagnostics.Add($"GfxObj 0x{gfx.Id:X8}: vertex id(s) {string.Join(", ", unusable.Order())} have NaN or infinite coordinates; left out, so polygons using them get no plane");

        // One list of the polygon's usable points, refilled per polygon (the plane code only reads it).
        var points = new List<Vector3>();
        foreach (var (id, poly) in InIdOrder(gfx.PhysicsPolygons))
        {
            var ids = new int[poly.VertexIds.Count];
            for (var i = 0; i < ids.Length; i++) ids[i] = poly.VertexIds[i];
            points.Clear();
            var missing = false;
            List<int>? absent = null;
            foreach (var v in ids)
            {
                if (!gfx.Vertices.TryGetValue((ushort)v, out var p)) (absent ??= []).Add(v);
                else if (!unusable.Contains(v))
                {
                    points.Add(p);
                    usedVertices.Add(v);
                    continue;
                }
                missing = true;
            }
            if (absent is not null)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: vertex id(s) {string.Join(", ", absent)} not in the vertex array");

            Plane? plane = missing ? null : PolygonPlane.Compute(points);
            if (ids.Length < 3)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} polygon {id}: {ids.Length} vertices, a polygon needs 3");
            if (plane is null)
            {
                degenerate.Add(id);
                if (!missing && ids.Length >= 3)
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

        // Polygon ids are ushort keys: one bit each answers a leaf's membership test.
        var polygonIds = new ulong[polygons.Count == 0 ? 0 : (polygons[^1].Id >> 6) + 1];
        foreach (var polygon in polygons) polygonIds[polygon.Id >> 6] |= 1UL << (polygon.Id & 63);
        var nodes = new List<BspNode>();
        int maxDepth = 0, droppedBelowLimit = 0, leafCount = 0, solidLeafCount = 0;
        Flatten(gfx.PhysicsBsp, 0);
        if (droppedBelowLimit > 0)
            diagnostics.Add($"GfxObj 0x{gfx.Id:X8}: the PhysicsBSP is deeper than {BspLimits.MaxDepth} levels, which no real one is; {droppedBelowLimit} subtree(s) below that depth are dropped");

        var vertices = Vertices(gfx.Vertices, usedVertices);
        var stats = new BspStats(vertices.Length, polygons.Count, nodes.Count, leafCount, solidLeafCount, maxDepth, degenerate, nonPlanar);
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
                var ids = new int[node.Polygons.Count];
                for (var i = 0; i < ids.Length; i++)
                {
                    ids[i] = node.Polygons[i];
                    if (!Contains(polygonIds, ids[i]))
                        diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP leaf {node.LeafIndex}: polygon id {ids[i]} is not a physics polygon");
                }
                leafCount++;
                if (node.Solid != 0) solidLeafCount++;
                nodes[index] = new BspNode(index, node.Type, null, node.BoundingSphere, null, null, node.LeafIndex, node.Solid != 0, ids);
                return index;
            }
            Plane? splitting = node.SplittingPlane;
            if (!IsFinite(node.SplittingPlane.Normal) || !float.IsFinite(node.SplittingPlane.D))
            {
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP node {index}: splitting plane has NaN or infinite values; written as absent");
                splitting = null;
            }
            // Retail's solid query (BSPNODE::sphere_intersects_solid) follows both children unchecked, so real
            // physics BSPs give every internal node both; the missing side is read as empty space, our choice.
            if (node.Pos is null || node.Neg is null)
                diagnostics.Add($"GfxObj 0x{gfx.Id:X8} BSP node {index} has no {(node.Pos is null ? "positive" : "negative")} child: retail's solid query would fail here; acshadow treats the missing side as empty space");
            var pos = node.Pos is null ? null : Flatten(node.Pos, depth + 1);
            var neg = node.Neg is null ? null : Flatten(node.Neg, depth + 1);
            nodes[index] = new BspNode(index, node.Type, splitting, node.BoundingSphere, pos, neg, 0, false, []);
            return index;
        }
    }

    /// <summary>The ids of vertices with a NaN or infinite coordinate; nearly always none, and then nothing is allocated.</summary>
    private static IReadOnlySet<int> NonFiniteVertices(IReadOnlyDictionary<ushort, Vector3> vertices)
    {
        HashSet<int>? found = null;
        foreach (var (id, position) in vertices)
            if (!IsFinite(position)) (found ??= []).Add(id);
        return found ?? NoVertices;
    }

    private static readonly HashSet<int> NoVertices = [];

    /// <summary>The dat stores physics polygons in id order; sorting (stably, as before) only when one does not.</summary>
    private static IEnumerable<KeyValuePair<ushort, Polygon>> InIdOrder(IReadOnlyList<KeyValuePair<ushort, Polygon>> polygons)
    {
        for (var i = 1; i < polygons.Count; i++)
            if (polygons[i].Key < polygons[i - 1].Key) return polygons.OrderBy(p => p.Key);
        return polygons;
    }

    private static bool Contains(ulong[] bits, int id) =>
        id >= 0 && (id >> 6) < bits.Length && (bits[id >> 6] & (1UL << (id & 63))) != 0;

    /// <summary>Each used vertex once, in id order.</summary>
    private static BspVertex[] Vertices(IReadOnlyDictionary<ushort, Vector3> positions, List<int> used)
    {
        int min = int.MaxValue, max = -1;
        foreach (var id in used)
        {
            min = Math.Min(min, id);
            max = Math.Max(max, id);
        }
        if (min >= 0) return VerticesByBit(positions, used, max);
        used.Sort();
        var distinct = 0;
        for (var i = 0; i < used.Count; i++)
            if (i == 0 || used[i] != used[i - 1]) used[distinct++] = used[i];
        var vertices = new BspVertex[distinct];
        for (var i = 0; i < distinct; i++) vertices[i] = new BspVertex(used[i], positions[(ushort)used[i]]);
        return vertices;
    }

    /// <summary>
    /// As <see cref="Vertices"/> when every id is 0 or more (the dat's ids are shorts; real ones are never
    /// negative): a bit per id puts them in order without sorting.
    /// </summary>
    private static BspVertex[] VerticesByBit(IReadOnlyDictionary<ushort, Vector3> positions, List<int> used, int max)
    {
        Span<ulong> seen = stackalloc ulong[(max >> 6) + 1];
        var distinct = 0;
        foreach (var id in used)
        {
            ref var word = ref seen[id >> 6];
            var bit = 1UL << (id & 63);
            if ((word & bit) != 0) continue;
            word |= bit;
            distinct++;
        }
        var vertices = new BspVertex[distinct];
        var n = 0;
        for (var w = 0; w < seen.Length; w++)
            for (var bits = seen[w]; bits != 0; bits &= bits - 1)
            {
                var id = (w << 6) + BitOperations.TrailingZeroCount(bits);
                vertices[n++] = new BspVertex(id, positions[(ushort)id]);
            }
        return vertices;
    }

    private static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
