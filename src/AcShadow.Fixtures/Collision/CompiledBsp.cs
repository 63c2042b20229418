using System.Collections.Immutable;
using System.Runtime.InteropServices;
using System.Globalization;
using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A <see cref="BspDump"/> checked and laid out in arrays for the sphere queries, whether the dump came
/// from a dat (BspExtractor) or from a JSON file (BspFileReader): both queries read only this.
/// Nothing in a dump makes compiling throw; every repair is a diagnostic naming the polygon or node:
/// polygons without a plane, with missing or non-finite vertices are skipped; a child index that is out of
/// range, not after its parent (preorder) or already someone's child is treated as absent; an internal node
/// without a finite plane gets the zero plane (both children visited, centre to the positive side); a
/// non-finite bounding sphere never rejects.
/// </summary>
internal sealed class CompiledBsp
{
    public uint GfxObjId { get; }
    public ImmutableArray<CompiledPolygon> Polygons { get; }
    public ImmutableArray<CompiledBspNode> Nodes { get; }
    /// <summary>Indices into <see cref="Polygons"/>, leaf by leaf (see <see cref="CompiledBspNode.PolygonStart"/>).</summary>
    public ImmutableArray<int> LeafPolygons { get; }
    /// <summary>Solid leaves reachable from the root that list at least one polygon, as ancestor paths.</summary>
    public IReadOnlyList<SolidCell> SolidCells { get; }
    /// <summary>True when no check found a way for the tree's pruning to miss a contact the brute force sees.</summary>
    public bool PruningIsConservative { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }

    private NearestPolygonIndex? _nearest;

    /// <summary>
    /// Built on first use and kept: only the chart's distance ranking needs it. Read without a delegate, which
    /// would be allocated on every call, and the ranking asks once per probe.
    /// </summary>
    internal NearestPolygonIndex Nearest => Volatile.Read(ref _nearest) ?? (Interlocked.CompareExchange(ref _nearest, NearestPolygonIndex.Build(Polygons), null) ?? _nearest);

    private CompiledBsp(uint id, CompiledPolygon[] polygons, CompiledBspNode[] nodes, int[] leafPolygons,
        IReadOnlyList<SolidCell> solidCells, bool conservative, IReadOnlyList<Diagnostic> diagnostics)
    {
        GfxObjId = id;
        // Wrapped, not copied: the arrays are built here and never handed out, so nothing can change them.
        Polygons = ImmutableCollectionsMarshal.AsImmutableArray(polygons);
        Nodes = ImmutableCollectionsMarshal.AsImmutableArray(nodes);
        LeafPolygons = ImmutableCollectionsMarshal.AsImmutableArray(leafPolygons);
        SolidCells = solidCells;
        PruningIsConservative = conservative;
        Diagnostics = diagnostics;
    }

    /// <summary>
    /// A convex solid as a one-leaf tree (movement.md §4.1: how the chart's part-boxes and part-hulls are run through
    /// BSPTREE::find_collisions): one solid leaf listing every face, in order, with <paramref name="center"/> and
    /// <paramref name="radius"/> as its bounding sphere, so its faces step, slide and carry walkable planes as
    /// a real part's polygons do.
    /// </summary>
    internal static CompiledBsp SolidLeaf(uint id, IReadOnlyList<CompiledPolygon> faces, Vector3 center, float radius)
    {
        var polygons = faces.ToArray();
        var leaf = new CompiledBspNode(true, center, radius, Vector3.Zero, 0f, -1, -1, true, polygons.Length, 0, polygons.Length, 0);
        var cells = polygons.Length > 0 ? new[] { new SolidCell(0, [], []) } : [];
        return new CompiledBsp(id, polygons, [leaf], [.. Enumerable.Range(0, polygons.Length)], cells, true, []);
    }

    public static CompiledBsp Compile(BspDump dump)
    {
        var log = new DiagnosticLog();
        var name = $"GfxObj 0x{dump.GfxObjId:X8}";
        var polygons = CompilePolygons(dump, name, log, out var polygonIndex);
        var nodes = new CompiledBspNode[dump.Nodes.Count];
        var leafPolygons = new List<int>();
        var hasParent = new bool[nodes.Length];
        var depth = new int[nodes.Length];
        var inertSolidLeaves = 0;
        var dumpPolygonIds = dump.Polygons.Select(p => p.Id).ToHashSet();

        for (var i = 0; i < nodes.Length; i++)
        {
            var node = dump.Nodes[i];
            var (center, radius) = SphereOf(node, i, name, log);
            if (node.IsLeaf)
            {
                var start = leafPolygons.Count;
                foreach (var id in node.PolygonIds)
                {
                    if (polygonIndex.TryGetValue(id, out var index)) leafPolygons.Add(index);
                    else if (!dumpPolygonIds.Contains(id))
                        log.Add(CollisionDiagnosticCodes.MissingPolygon, $"{name} BSP leaf {node.LeafIndex} (node {i}): polygon id {id} is not a physics polygon; ignored");
                }
                if (node.Solid && node.PolygonIds.Count == 0) inertSolidLeaves++;
                nodes[i] = new CompiledBspNode(true, center, radius, Vector3.Zero, 0f, -1, -1, node.Solid,
                    node.PolygonIds.Count, start, leafPolygons.Count - start, node.LeafIndex);
                continue;
            }
            var normal = Vector3.Zero;
            var d = 0f;
            if (node.Plane is { } plane && Vec.IsFinite(plane.Normal) && float.IsFinite(plane.D))
            {
                normal = plane.Normal;
                d = plane.D;
            }
            else
            {
                log.Add(CollisionDiagnosticCodes.MalformedNode, $"{name} BSP node {i}: internal node without a finite splitting plane; both children are visited and the centre goes to the positive side");
            }
            var pos = Child(node.Pos, i, "positive", nodes.Length, hasParent, depth, name, log);
            var neg = Child(node.Neg, i, "negative", nodes.Length, hasParent, depth, name, log);
            nodes[i] = new CompiledBspNode(false, center, radius, normal, d, pos, neg, false, 0, 0, 0, 0);
        }

        if (nodes.Length == 0)
            log.Add(CollisionDiagnosticCodes.EmptyTree, $"{name}: the PhysicsBSP has no nodes; nothing of it collides");
        if (inertSolidLeaves > 0)
            log.Add(CollisionDiagnosticCodes.InertSolidLeaf,
                $"{name}: {inertSolidLeaves} solid leaf/leaves hold no polygons; BSPLEAF::sphere_intersects_solid returns on NumPolys == 0 before its centre check, so they never block");

        var reachable = Reachable(nodes);
        var unreachable = Enumerable.Range(0, nodes.Length).Count(i => !reachable[i]);
        if (unreachable > 0)
            log.Add(CollisionDiagnosticCodes.MalformedNode, $"{name}: {unreachable} node(s) cannot be reached from the root and are never visited");

        var leafArray = leafPolygons.ToArray();
        var cells = SolidCellsOf(nodes, reachable);
        var conservative = BspConsistency.Check(name, polygons, nodes, leafArray, reachable, log);
        return new CompiledBsp(dump.GfxObjId, polygons, nodes, leafArray, cells, conservative, log.ToList());
    }

    private static CompiledPolygon[] CompilePolygons(BspDump dump, string name, DiagnosticLog log, out Dictionary<int, int> index)
    {
        var vertices = new Dictionary<int, Vector3>();
        foreach (var v in dump.Vertices) vertices.TryAdd(v.Id, v.Position);
        var nonPlanar = dump.Stats.NonPlanarPolygons.ToHashSet();
        var compiled = new List<CompiledPolygon>(dump.Polygons.Count);
        index = new Dictionary<int, int>();
        foreach (var polygon in dump.Polygons)
        {
            var what = $"{name} polygon {polygon.Id}";
            if (index.ContainsKey(polygon.Id)) { log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: duplicate id; the later copy is skipped"); continue; }
            if (polygon.Plane is not { } plane) { log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: degenerate (no plane: collinear, repeated or missing vertices); never tested"); continue; }
            if (polygon.VertexIds.Count < 3) { log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: {polygon.VertexIds.Count} vertices; never tested"); continue; }
            if (!Vec.IsFinite(plane.Normal) || !float.IsFinite(plane.D)) { log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: non-finite plane; never tested"); continue; }
            var points = new Vector3[polygon.VertexIds.Count];
            var usable = true;
            for (var k = 0; k < points.Length && usable; k++)
            {
                if (!vertices.TryGetValue(polygon.VertexIds[k], out points[k]))
                {
                    log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: vertex id {polygon.VertexIds[k]} is not in the vertex list; never tested");
                    usable = false;
                }
                else if (!Vec.IsFinite(points[k]))
                {
                    log.Add(CollisionDiagnosticCodes.SkippedPolygon, $"{what}: vertex {polygon.VertexIds[k]} is not finite; never tested");
                    usable = false;
                }
            }
            if (!usable) continue;
            if (nonPlanar.Contains(polygon.Id))
                log.Add(CollisionDiagnosticCodes.NonPlanarPolygon, $"{what}: non-planar; tested against its averaged plane, as retail does");
            index[polygon.Id] = compiled.Count;
            compiled.Add(new CompiledPolygon(polygon.Id, plane, points));
        }
        return [.. compiled];
    }

    private static (Vector3 Center, float Radius) SphereOf(BspNode node, int i, string name, DiagnosticLog log)
    {
        var s = node.Sphere;
        if (Vec.IsFinite(s.Center) && float.IsFinite(s.Radius)) return (s.Center, s.Radius);
        log.Add(CollisionDiagnosticCodes.MalformedNode, $"{name} BSP node {i}: non-finite bounding sphere; it never rejects");
        return (Vector3.Zero, float.PositiveInfinity);
    }

    /// <summary>Children come after their parent, so the parent's depth is known when its children are checked.</summary>
    private static int Child(int? child, int parent, string side, int count, bool[] hasParent, int[] depth, string name, DiagnosticLog log)
    {
        if (child is not { } c) return -1;
        string? problem = null;
        if (c < 0 || c >= count) problem = "is out of range";
        else if (c <= parent) problem = "does not come after its parent (the list is preorder)";
        else if (hasParent[c]) problem = "is already another node's child";
        else if (depth[parent] + 1 > BspLimits.MaxDepth) problem = $"lies deeper than {BspLimits.MaxDepth} levels, which no real PhysicsBSP does";
        if (problem is not null)
        {
            log.Add(CollisionDiagnosticCodes.MalformedNode, $"{name} BSP node {parent}: {side} child index {c.ToString(CultureInfo.InvariantCulture)} {problem}; treated as absent");
            return -1;
        }
        hasParent[c] = true;
        depth[c] = depth[parent] + 1;
        return c;
    }

    private static bool[] Reachable(CompiledBspNode[] nodes)
    {
        var reachable = new bool[nodes.Length];
        if (nodes.Length == 0) return reachable;
        var stack = new Stack<int>();
        stack.Push(0);
        while (stack.Count > 0)
        {
            var i = stack.Pop();
            reachable[i] = true;
            if (nodes[i].IsLeaf) continue;
            if (nodes[i].Pos >= 0) stack.Push(nodes[i].Pos);
            if (nodes[i].Neg >= 0) stack.Push(nodes[i].Neg);
        }
        return reachable;
    }

    private static List<SolidCell> SolidCellsOf(CompiledBspNode[] nodes, bool[] reachable)
    {
        var cells = new List<SolidCell>();
        if (nodes.Length == 0) return cells;
        var path = new List<int>();
        var sides = new List<bool>();
        Walk(0);
        return cells;

        void Walk(int i)
        {
            var node = nodes[i];
            if (node.IsLeaf)
            {
                if (node.Solid && node.ListedPolygonCount > 0 && reachable[i]) cells.Add(new SolidCell(i, [.. path], [.. sides]));
                return;
            }
            foreach (var (child, pos) in new[] { (node.Pos, true), (node.Neg, false) })
            {
                if (child < 0) continue;
                path.Add(i);
                sides.Add(pos);
                Walk(child);
                path.RemoveAt(path.Count - 1);
                sides.RemoveAt(sides.Count - 1);
            }
        }
    }
}
