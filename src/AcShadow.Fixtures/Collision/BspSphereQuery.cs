using System.Runtime.InteropServices;
using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The collision reference for one GfxObj: a static sphere overlap answered the way retail answers a
/// placement test (BSPTREE::find_collisions with InsertType Placement → BSPNODE::sphere_intersects_solid
/// with the centre check on), in part-local space.
/// <list type="bullet">
/// <item>first the broad phase of CGfxObj::find_obj_collisions against the root's sphere;</item>
/// <item>a node whose bounding sphere the query sphere misses is rejected;</item>
/// <item>at an internal node, dist = dot(normal, centre) + d and reach = r − ε: dist ≥ reach visits only
/// the positive child, dist ≤ −reach only the negative one, otherwise both, and the centre check follows
/// the side the centre is on (negative when dist &lt; 0);</item>
/// <item>at a leaf (BSPLEAF::sphere_intersects_solid): no listed polygons → clear; centre check on and
/// solid → blocked; otherwise, if its sphere is hit, blocked when the sphere touches one of its polygons
/// (<see cref="PolygonSphereTest"/>).</item>
/// </list>
/// An absent child is empty space. Thread-safe: queries share only read-only arrays.
/// </summary>
internal sealed class BspSphereQuery : ISphereOverlap
{
    private readonly CompiledPolygon[] _polygons;
    private readonly CompiledBspNode[] _nodes;
    private readonly int[] _leafPolygons;
    /// <summary>
    /// Each <see cref="_leafPolygons"/> entry's plane (normal, d), side by side in leaf order: the plane
    /// test that rejects most polygons reads one contiguous run instead of chasing a polygon object each.
    /// </summary>
    private readonly Vector4[] _leafPlanes;
    /// <summary>
    /// Each entry's polygon bounding sphere (centre, radius plus slack), beside <see cref="_leafPlanes"/>:
    /// a polygon on a plane the query reaches but far from its centre is dismissed without the edge walk.
    /// </summary>
    private readonly Vector4[] _leafSpheres;
    /// <summary>The most pending nodes a traversal can hold: one per level of the deepest path, plus one.</summary>
    private readonly int _stackSize;

    public CompiledBsp Bsp { get; }

    public BspSphereQuery(CompiledBsp bsp)
    {
        Bsp = bsp;
        _polygons = ImmutableCollectionsMarshal.AsArray(bsp.Polygons)!;
        _nodes = ImmutableCollectionsMarshal.AsArray(bsp.Nodes)!;
        _leafPolygons = ImmutableCollectionsMarshal.AsArray(bsp.LeafPolygons)!;
        _leafPlanes = Array.ConvertAll(_leafPolygons, k => new Vector4(_polygons[k].Normal, _polygons[k].D));
        _leafSpheres = Array.ConvertAll(_leafPolygons, k => BoundingSphereOf(_polygons[k]));
        _stackSize = StackSizeOf(_nodes);
    }

    public static BspSphereQuery From(BspDump dump) => new(CompiledBsp.Compile(dump));

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius) || _nodes.Length == 0) return false;
        if (!SphereBounds.BroadPhaseHits(_nodes[0], center, radius)) return false;
        return Walk(1, center, radius, radius - PhysicsEpsilon.Value);
    }

    /// <summary>
    /// The walk below one node entered with the centre check on or off, as <see cref="Overlaps"/> walks it there:
    /// the answer of a reached node's subtree does not depend on the rest of the walk, which is what lets
    /// <see cref="BspReachGrid"/> hand over only the nodes its voxel leaves undecided. No probe checks.
    /// </summary>
    internal bool WalkFrom(int node, bool centreCheck, Vector3 center, float radius, float reach) =>
        Walk(node << 1 | (centreCheck ? 1 : 0), center, radius, reach);

    /// <summary>One listed polygon (an index into the leaf order) as <see cref="LeafTouches"/> tests it.</summary>
    internal bool EntryTouches(int entry, Vector3 center, float radius, float reach) => LeafTouches(entry, 1, center, radius, reach);

    /// <summary>
    /// One listed polygon's first rejection alone, as <see cref="LeafTouches"/> and <see cref="PolygonSphereTest.Touches"/>
    /// make it (|dist| &gt; r − ε, the same float operations): the whole test where the centre's contact point is
    /// known to lie inside the polygon and its bounding sphere known to be met (<see cref="BspBoxWalk"/>).
    /// </summary>
    internal bool EntryReachesPlane(int entry, Vector3 center, float reach)
    {
        ref readonly var plane = ref _leafPlanes[entry];
        var dist = plane.X * center.X + plane.Y * center.Y + plane.Z * center.Z + plane.W;
        return !(MathF.Abs(dist) > reach);
    }

    /// <summary>A listed polygon by its entry in leaf order.</summary>
    internal CompiledPolygon LeafPolygon(int entry) => _polygons[_leafPolygons[entry]];

    internal ReadOnlySpan<CompiledBspNode> Nodes => _nodes;

    /// <summary>The plane <see cref="LeafTouches"/> rejects a listed polygon by, per entry.</summary>
    internal ReadOnlySpan<Vector4> LeafPlanes => _leafPlanes;

    /// <summary>The bounding sphere <see cref="LeafTouches"/> rejects a listed polygon by, per entry.</summary>
    internal ReadOnlySpan<Vector4> LeafSpheres => _leafSpheres;

    private bool Walk(int entry0, Vector3 center, float radius, float reach)
    {
        // Entries are node << 1 | centre-check. Sized by the tree's height, not its node count, so a query
        // neither allocates nor clears a node-sized buffer.
        Span<int> stack = stackalloc int[_stackSize];
        var top = 0;
        stack[top++] = entry0;
        while (top > 0)
        {
            var entry = stack[--top];
            ref readonly var node = ref _nodes[entry >> 1];
            var centreCheck = (entry & 1) != 0;
            if (node.IsLeaf)
            {
                if (node.ListedPolygonCount == 0) continue;
                if (centreCheck && node.Solid) return true;
                if (!SphereBounds.NodeSphereHits(node, center, radius)) continue;
                if (LeafTouches(node.PolygonStart, node.PolygonCount, center, radius, reach)) return true;
                continue;
            }
            if (!SphereBounds.NodeSphereHits(node, center, radius)) continue;
            var dist = PolygonPlane.Dot(node.Normal, center) + node.D;
            if (dist >= reach) Push(stack, ref top, node.Pos, centreCheck);
            else if (dist <= -reach) Push(stack, ref top, node.Neg, centreCheck);
            else if (dist < 0f)
            {
                Push(stack, ref top, node.Pos, false);
                Push(stack, ref top, node.Neg, centreCheck);
            }
            else
            {
                Push(stack, ref top, node.Pos, centreCheck);
                Push(stack, ref top, node.Neg, false);
            }
        }
        return false;
    }

    /// <summary>
    /// <see cref="PolygonSphereTest.Touches"/> over a leaf's polygons, its first rejection (|dist| &gt; r − ε,
    /// the same float operations in the same order) done here on the packed planes.
    /// </summary>
    private bool LeafTouches(int start, int count, Vector3 center, float radius, float reach)
    {
        var planes = _leafPlanes.AsSpan(start, count);
        for (var k = 0; k < planes.Length; k++)
        {
            ref readonly var plane = ref planes[k];
            var dist = plane.X * center.X + plane.Y * center.Y + plane.Z * center.Z + plane.W;
            if (MathF.Abs(dist) > reach) continue;
            ref readonly var sphere = ref _leafSpheres[start + k];
            float dx = center.X - sphere.X, dy = center.Y - sphere.Y, dz = center.Z - sphere.Z, sum = sphere.W + radius;
            if (dx * dx + dy * dy + dz * dz > sum * sum) continue;
            if (PolygonSphereTest.Touches(_polygons[_leafPolygons[start + k]], center, radius)) return true;
        }
        return false;
    }

    /// <summary>
    /// A sphere no touching query can miss. PolygonSphereTest hits only through a point q of the polygon's
    /// plane inside the hull of the vertices' projections with |centre − q| ≤ r − ε, so |centre − c| ≤
    /// r + max|v − c| + |plane distance of c|. The slack covers that last term, non-planar vertices and
    /// float rounding many times over; it only lets a few more polygons through to the exact test.
    /// </summary>
    private static Vector4 BoundingSphereOf(CompiledPolygon polygon)
    {
        var vertices = polygon.Vertices;
        double cx = 0, cy = 0, cz = 0;
        foreach (var v in vertices) { cx += v.X; cy += v.Y; cz += v.Z; }
        cx /= vertices.Length; cy /= vertices.Length; cz /= vertices.Length;
        double reachOut = 0, deviation = 0, scale = Math.Abs(cx) + Math.Abs(cy) + Math.Abs(cz);
        foreach (var v in vertices)
        {
            double dx = v.X - cx, dy = v.Y - cy, dz = v.Z - cz;
            reachOut = Math.Max(reachOut, Math.Sqrt(dx * dx + dy * dy + dz * dz));
            deviation = Math.Max(deviation, Math.Abs((double)polygon.Normal.X * v.X + (double)polygon.Normal.Y * v.Y + (double)polygon.Normal.Z * v.Z + polygon.D));
        }
        var slack = 4 * deviation + 1e-4 * (scale + reachOut) + 1e-3;
        var radius = (float)(reachOut + slack);
        return float.IsFinite(radius) ? new Vector4((float)cx, (float)cy, (float)cz, radius) : new Vector4(0f, 0f, 0f, float.PositiveInfinity);
    }

    /// <summary>
    /// Popping a node at depth k leaves at most one pending sibling per level above it and pushes two
    /// children: never more than height + 2 entries. Children come after their parent (CompiledBsp
    /// enforces preorder), so one forward pass finds every depth.
    /// </summary>
    private static int StackSizeOf(CompiledBspNode[] nodes)
    {
        var depth = new int[nodes.Length];
        var height = 0;
        for (var i = 0; i < nodes.Length; i++)
        {
            height = Math.Max(height, depth[i]);
            if (nodes[i].IsLeaf) continue;
            if (nodes[i].Pos >= 0) depth[nodes[i].Pos] = depth[i] + 1;
            if (nodes[i].Neg >= 0) depth[nodes[i].Neg] = depth[i] + 1;
        }
        return height + 2;
    }

    private static void Push(Span<int> stack, ref int top, int child, bool centreCheck)
    {
        if (child >= 0) stack[top++] = child << 1 | (centreCheck ? 1 : 0);
    }
}
