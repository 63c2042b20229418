using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A tree trimmed to what a mover of one radius can reach: <see cref="BspSphereQuery.Overlaps"/> decided ahead of
/// time over the voxels of a grid around the tree's root sphere, in part-local space. Each voxel is Clear (the walk
/// answers false for every centre in it), Blocked (true for every centre) or a frontier: the nodes (with their
/// centre-check flag) and single listed polygons the walk's decisions leave open there. The walk's answer is an OR
/// over what it reaches and a reached node's subtree answers independently of the rest, so running the frontier's
/// items exactly (<see cref="BspSphereQuery.WalkFrom"/>, <see cref="BspSphereQuery.EntryTouches"/>) gives the walk's
/// answer bit for bit.
/// <para>Exact for any tree, however malformed (polygons across split planes, node spheres that do not bound
/// their polygons, solid leaves without polygons): the build runs the walk's own code over a voxel's box with
/// interval arithmetic, the box padded so every float centre that maps to the voxel lies inside it, and every
/// comparison padded by a bound on the float rounding of the walk's evaluation. Only a decision that comes out the
/// same for the whole padded box is taken. One that is not leaves a guard on the frontier (the node's sphere test,
/// or its push of one child: the same float test the walk makes) over what lies behind it, or, where the centre
/// check would depend on the centre's side, the node itself.</para>
/// <para>Built as an octree under a coarse grid: a child box starts from its parent's frontier (a decision uniform
/// over the parent stays so over the child), so empty space is settled in large cells and the voxel budget goes to
/// the cells whose frontier costs most. A centre outside the grid, or a radius other than <see cref="Radius"/>, is
/// not for this index (<see cref="IndexedBspQuery"/> walks the tree then). Immutable after the build: reads are
/// thread-safe and allocate nothing.</para>
/// </summary>
internal sealed class BspReachGrid
{
    // A cell's code: one of these, a frontier (FrontierBase + its offset in _items, which holds count << 1 | guarded
    // then the items), or minus the index of its eight children in _cells. Guarded: the root's broad phase is not
    // decided over the cell, so it is asked first (a Guarded-blocked cell answers by it alone). Outside: no cell.
    private const int ClearCode = 0, BlockedCode = 1, GuardedBlockedCode = 2, FrontierBase = 3, OutsideCode = int.MaxValue;
    /// <summary>Octree levels under a top cell: the finest voxel is a top cell's edge / 16.</summary>
    private const int Levels = 4;
    /// <summary>At most this many finest voxels along an axis (the top grid then has 8).</summary>
    private const int MaxFine = 128;
    /// <summary>At most this many cell codes per grid (4 bytes each), children blocks included.</summary>
    private const int CellBudget = 1 << 12;
    /// <summary>A frontier cheaper than this (in nodes and polygons a walk would look at) is not split further.</summary>
    private const int SplitCost = 3;

    // A frontier item: payload << 2 | tag. Node: payload node << 1 | centre check, walked from there. Polygon:
    // payload the listed-polygon entry. Guard: payload node << 2 | kind, then the length of the block it guards,
    // skipped when the guard fails. True: blocks.
    private const int NodeTag = 0, PolygonTag = 1, GuardTag = 2, TrueItem = 3;
    private const int SphereGuard = 0, PushesPosGuard = 1, PushesNegGuard = 2;

    private readonly BspSphereQuery _tree;
    private readonly CompiledBspNode[] _nodes;
    private readonly CompiledBspNode _root;
    private readonly float _reach;
    private readonly Vector3 _origin;
    private readonly float _inverseFine;
    private readonly int _top;
    private readonly int _fine;
    private readonly int[] _cells;
    private readonly int[] _items;

    public float Radius { get; }

    /// <summary>The grid's least corner, part-local.</summary>
    internal Vector3 Origin => _origin;

    /// <summary>The finest voxel's edge, as a centre is mapped to its voxel (times this, floored).</summary>
    internal float InverseVoxelEdge => _inverseFine;

    /// <summary>What the index holds, in bytes: its cell codes and frontier items.</summary>
    public long Bytes => 4L * (_cells.Length + _items.Length);

    private BspReachGrid(BspSphereQuery tree, float radius, Vector3 origin, float inverseFine, int top, int[] cells, int[] items)
    {
        _tree = tree;
        _nodes = tree.Nodes.ToArray();
        _root = _nodes[0];
        Radius = radius;
        _reach = radius - PhysicsEpsilon.Value;
        _origin = origin;
        _inverseFine = inverseFine;
        _top = top;
        _fine = top << Levels;
        _cells = cells;
        _items = items;
    }

    /// <summary>The index of <paramref name="tree"/> for one radius, or null when there is nothing to index (no nodes, no finite root sphere, an unusable radius).</summary>
    public static BspReachGrid? Build(BspSphereQuery tree, float radius)
    {
        var nodes = tree.Nodes;
        if (nodes.Length == 0 || !SphereBounds.IsValidProbe(Vector3.Zero, radius)) return null;
        var root = nodes[0];
        if (!float.IsFinite(root.SphereRadius) || root.SphereRadius < 0f || !float.IsFinite(root.SphereCenter.Length())) return null;
        var half = (double)root.SphereRadius + radius;
        half += 1e-3 * (half + root.SphereCenter.Length()) + 1e-3;
        if (!(half < 1e5)) return null;
        var fine = Math.Max(radius / 4.0, 2 * half / MaxFine);
        var inverseFine = (float)(1.0 / fine);
        var top = (int)Math.Ceiling(2 * half * inverseFine / (1 << Levels));
        var c = root.SphereCenter;
        var origin = new Vector3((float)(c.X - half), (float)(c.Y - half), (float)(c.Z - half));
        var (cells, items) = new Builder(tree, radius, origin, inverseFine, top).Run();
        return new BspReachGrid(tree, radius, origin, inverseFine, top, cells, items);
    }

    /// <summary><see cref="BspSphereQuery.Overlaps"/> at this centre with <see cref="Radius"/>.</summary>
    public bool Overlaps(Vector3 center)
    {
        var code = Code(center);
        if (code == ClearCode) return false;
        if (code == BlockedCode) return true;
        if (code == OutsideCode) return _tree.Overlaps(center, Radius);
        var frontier = Frontier(code, out var guarded);
        if (guarded && !SphereBounds.BroadPhaseHits(_root, center, Radius)) return false;
        if (code == GuardedBlockedCode) return true;
        for (var i = 0; i < frontier.Length;)
        {
            var item = frontier[i++];
            switch (item & 3)
            {
                case NodeTag:
                    if (_tree.WalkFrom(item >> 3, (item & 4) != 0, center, Radius, _reach)) return true;
                    break;
                case PolygonTag:
                    if (_tree.EntryTouches(item >> 2, center, Radius, _reach)) return true;
                    break;
                case GuardTag:
                    var length = frontier[i++];
                    if (!Passes(item >> 2, center)) i += length;
                    break;
                default:
                    return true;
            }
        }
        return false;
    }

    /// <summary>A guard as the walk decides it at this centre: the node's sphere test, or whether it pushes that child.</summary>
    internal bool Passes(int guard, Vector3 center)
    {
        ref readonly var node = ref _nodes[guard >> 2];
        if ((guard & 3) == SphereGuard) return SphereBounds.NodeSphereHits(node, center, Radius);
        var dist = PolygonPlane.Dot(node.Normal, center) + node.D;
        return (guard & 3) == PushesPosGuard ? dist >= _reach || !(dist <= -_reach) : !(dist >= _reach);
    }

    internal static bool IsNodeItem(int item, out int node, out bool centreCheck)
    {
        node = item >> 3;
        centreCheck = (item & 4) != 0;
        return (item & 3) == NodeTag;
    }

    internal static bool IsPolygonItem(int item, out int entry)
    {
        entry = item >> 2;
        return (item & 3) == PolygonTag;
    }

    /// <summary>A guard item: the guard to ask (<see cref="Passes"/>); the next int is the length of the block to skip when it fails.</summary>
    internal static bool IsGuard(int item, out int guard)
    {
        guard = item >> 2;
        return (item & 3) == GuardTag;
    }

    /// <summary>
    /// The code of the voxel holding a centre: <see cref="IsClear"/>, <see cref="IsBlocked"/>, a frontier or the
    /// root's broad phase alone (<see cref="Frontier"/>), or <see cref="IsOutside"/> the grid (the whole walk).
    /// </summary>
    internal int Code(Vector3 center)
    {
        var fx = (center.X - _origin.X) * _inverseFine;
        var fy = (center.Y - _origin.Y) * _inverseFine;
        var fz = (center.Z - _origin.Z) * _inverseFine;
        if (!(fx >= 0f && fx < _fine && fy >= 0f && fy < _fine && fz >= 0f && fz < _fine)) return OutsideCode;
        int ix = (int)fx, iy = (int)fy, iz = (int)fz;
        var code = _cells[((ix >> Levels) * _top + (iy >> Levels)) * _top + (iz >> Levels)];
        for (var level = Levels - 1; code < 0; level--)
            code = _cells[-code + ((ix >> level) & 1 | ((iy >> level) & 1) << 1 | ((iz >> level) & 1) << 2)];
        return code;
    }

    internal static bool IsClear(int code) => code == ClearCode;

    internal static bool IsBlocked(int code) => code == BlockedCode;

    internal static bool IsOutside(int code) => code == OutsideCode;

    /// <summary>
    /// A cell's frontier (nodes, polygons, guards over blocks, true: <see cref="IsNodeItem"/>, <see cref="IsPolygonItem"/>,
    /// <see cref="IsGuard"/>; anything else blocks), and whether the root's broad phase must pass first; a guarded
    /// cell without items blocks when it passes. Empty for clear and blocked cells.
    /// </summary>
    internal ReadOnlySpan<int> Frontier(int code, out bool guarded)
    {
        guarded = code == GuardedBlockedCode;
        if (code < FrontierBase || code == OutsideCode) return [];
        var header = _items[code - FrontierBase];
        guarded = (header & 1) != 0;
        return _items.AsSpan(code - FrontierBase + 1, header >> 1);
    }

    /// <summary>How many cells of each kind the grid holds (octree leaves, whatever their size); guarded: the root's broad phase asked first.</summary>
    internal (int Clear, int Blocked, int Frontier, int Guarded) StateCounts()
    {
        int clear = 0, blocked = 0, frontier = 0, guarded = 0;
        foreach (var code in _cells)
        {
            if (code < 0) continue;
            if (code == ClearCode) clear++;
            else if (code == BlockedCode) blocked++;
            else frontier++;
            if (code >= GuardedBlockedCode) { Frontier(code, out var g); if (g) guarded++; }
        }
        return (clear, blocked, frontier, guarded);
    }

    private enum Tri { False, True, Mixed }

    private readonly record struct Box(double LoX, double LoY, double LoZ, double HiX, double HiY, double HiZ);

    /// <summary>
    /// A cell waiting to be split: where its code is, its place at its level, and the frontier its children start
    /// from (null: the walk from the root; guarded: the root's broad phase still undecided).
    /// </summary>
    private sealed record Pending(int Slot, int Level, int X, int Y, int Z, int[]? Items, bool Guarded, long Cost);

    /// <summary>The build: deterministic (no threads, fixed orders), so the same tree always gives the same grid.</summary>
    private sealed class Builder
    {
        /// <summary>Relative bound on the float rounding of a squared distance or of R + r squared, with room to spare.</summary>
        private const double SquareSlack = 4e-6;
        private const double Tiny = 1e-30;
        /// <summary>Past this magnitude a float evaluation may overflow: the decision is left to the walk.</summary>
        private const double Huge = 1e30;

        private readonly CompiledBspNode[] _nodes;
        private readonly Vector4[] _planes;
        private readonly Vector4[] _spheres;
        private readonly float _radius;
        private readonly double _reach;
        private readonly Vector3 _origin;
        private readonly double _fine;
        private readonly double _pad;
        private readonly int _top;
        private readonly long[] _subtreeCost;
        private readonly List<int> _cells = [];
        private readonly List<int> _items = [];
        private readonly Dictionary<string, int> _frontiers = new(StringComparer.Ordinal);
        private readonly List<int> _scratch = [];

        public Builder(BspSphereQuery tree, float radius, Vector3 origin, float inverseFine, int top)
        {
            _nodes = tree.Nodes.ToArray();
            _planes = tree.LeafPlanes.ToArray();
            _spheres = tree.LeafSpheres.ToArray();
            _radius = radius;
            _reach = radius - PhysicsEpsilon.Value;
            _origin = origin;
            _fine = 1.0 / inverseFine;
            _top = top;
            // Every float centre whose (c − origin) · inverse floors to a voxel lies within a few ulps of the grid's
            // extent of the voxel's nominal box.
            var extent = _fine * (top << Levels);
            _pad = 1e-6 * (extent + Math.Abs(origin.X) + Math.Abs(origin.Y) + Math.Abs(origin.Z)) + 1e-6;
            _subtreeCost = new long[_nodes.Length];
            for (var i = _nodes.Length - 1; i >= 0; i--)
            {
                var node = _nodes[i];
                _subtreeCost[i] = 1 + (node.IsLeaf ? node.PolygonCount
                    : (node.Pos >= 0 ? _subtreeCost[node.Pos] : 0) + (node.Neg >= 0 ? _subtreeCost[node.Neg] : 0));
            }
        }

        public (int[] Cells, int[] Items) Run()
        {
            var pending = new List<Pending>();
            for (var x = 0; x < _top; x++)
                for (var y = 0; y < _top; y++)
                    for (var z = 0; z < _top; z++)
                    {
                        _cells.Add(0);
                        Settle(new Pending(_cells.Count - 1, 0, x, y, z, null, true, 0), pending);
                    }
            // Level by level, the costliest frontiers first, while the budget lasts.
            for (var level = 0; level < Levels && pending.Count > 0; level++)
            {
                var splitting = pending.Where(p => p.Level == level).OrderByDescending(p => p.Cost).ThenBy(p => p.Slot).ToList();
                pending.RemoveAll(p => p.Level == level);
                foreach (var cell in splitting)
                {
                    if (_cells.Count + 8 > CellBudget) break;
                    var first = _cells.Count;
                    _cells[cell.Slot] = -first;
                    for (var k = 0; k < 8; k++) _cells.Add(0);
                    for (var k = 0; k < 8; k++)
                        Settle(new Pending(first + k, level + 1, cell.X * 2 + (k & 1), cell.Y * 2 + (k >> 1 & 1), cell.Z * 2 + (k >> 2 & 1), cell.Items, cell.Guarded, 0), pending);
                }
            }
            return ([.. _cells], [.. _items]);
        }

        /// <summary>Classifies one cell from its parent's frontier, writes its code, and queues it for splitting when its frontier is worth it.</summary>
        private void Settle(Pending cell, List<Pending> pending)
        {
            var box = BoxOf(cell.Level, cell.X, cell.Y, cell.Z);
            _scratch.Clear();
            var guarded = false;
            if (cell.Guarded)
            {
                var broad = BroadPhase(_nodes[0], box);
                if (broad == Tri.False) { _cells[cell.Slot] = ClearCode; return; }
                guarded = broad == Tri.Mixed;
            }
            var blocked = cell.Items is null ? Visit(0, true, box) : Replay(cell.Items, 0, cell.Items.Length, box);
            if (blocked) { _cells[cell.Slot] = guarded ? GuardedBlockedCode : BlockedCode; return; }
            if (_scratch.Count == 0) { _cells[cell.Slot] = ClearCode; return; }
            int[] items = [.. _scratch];
            _cells[cell.Slot] = FrontierBase + Store(items, guarded);
            long cost = guarded ? 1 : 0;
            for (var i = 0; i < items.Length; i++)
            {
                cost += IsNodeItem(items[i], out var node, out _) ? _subtreeCost[node] : 1;
                if (IsGuard(items[i], out _)) i++;
            }
            if (cell.Level < Levels && cost >= SplitCost) pending.Add(cell with { Items = items, Guarded = guarded, Cost = cost });
        }

        /// <summary>
        /// A parent's frontier over a child's box: each node walked again as <see cref="Visit"/> walks it, each polygon
        /// tested again, each guard decided again (a block whose guard now always passes is inlined, one that never
        /// passes dropped). True when what is replayed blocks for every centre under the guards open around it.
        /// </summary>
        private bool Replay(int[] program, int from, int to, in Box box)
        {
            for (var i = from; i < to;)
            {
                var item = program[i++];
                if (IsNodeItem(item, out var node, out var centreCheck)) { if (Visit(node, centreCheck, box)) return true; }
                else if (IsPolygonItem(item, out var entry)) { if (!PolygonSkipped(entry, box)) _scratch.Add(item); }
                else if (IsGuard(item, out var guard))
                {
                    var end = i + 1 + program[i];
                    i++;
                    switch (GuardOver(guard, box))
                    {
                        case Tri.True:
                            if (Replay(program, i, end, box)) return true;
                            break;
                        case Tri.Mixed:
                            var mark = Open(guard);
                            Close(mark, Replay(program, i, end, box));
                            break;
                    }
                    i = end;
                }
                else return true;
            }
            return false;
        }

        private Tri GuardOver(int guard, in Box box)
        {
            var node = _nodes[guard >> 2];
            if ((guard & 3) == SphereGuard) return SphereHits(node.SphereCenter, node.SphereRadius, box);
            var (atLeast, atMost) = Pushes(node, box);
            return (guard & 3) == PushesPosGuard ? atLeast : atMost;
        }

        /// <summary>Whether the walk pushes the positive child (dist ≥ reach or not dist ≤ −reach) and the negative one (not dist ≥ reach), over the box.</summary>
        private (Tri Pos, Tri Neg) Pushes(in CompiledBspNode node, in Box box)
        {
            var (min, max) = PlaneRange(node.Normal, node.D, box);
            var positive = Compare(min, max, _reach, atLeast: true);
            var negative = Compare(min, max, -_reach, atLeast: false);
            return (Or(positive, Not(negative)), Not(positive));
        }

        private static Tri Not(Tri t) => t switch { Tri.True => Tri.False, Tri.False => Tri.True, _ => Tri.Mixed };

        private static Tri Or(Tri a, Tri b) => a == Tri.True || b == Tri.True ? Tri.True : a == Tri.False && b == Tri.False ? Tri.False : Tri.Mixed;

        /// <summary>Starts a guarded block: the guard, then its length, filled in by <see cref="Close"/>.</summary>
        private int Open(int guard)
        {
            var mark = _scratch.Count;
            _scratch.Add(guard << 2 | GuardTag);
            _scratch.Add(0);
            return mark;
        }

        /// <summary>Ends a guarded block: one that blocks whenever its guard passes becomes just that; an empty one is dropped.</summary>
        private void Close(int mark, bool blocks)
        {
            if (blocks)
            {
                _scratch.RemoveRange(mark + 2, _scratch.Count - mark - 2);
                _scratch.Add(TrueItem);
            }
            var length = _scratch.Count - mark - 2;
            if (length == 0) _scratch.RemoveRange(mark, 2);
            else _scratch[mark + 1] = length;
        }

        /// <summary>Frontiers repeat from voxel to voxel: each distinct one is stored once.</summary>
        private int Store(int[] items, bool guarded)
        {
            var key = (guarded ? "g" : "") + string.Join(',', items);
            if (_frontiers.TryGetValue(key, out var offset)) return offset;
            offset = _items.Count;
            _items.Add(items.Length << 1 | (guarded ? 1 : 0));
            _items.AddRange(items);
            _frontiers[key] = offset;
            return offset;
        }

        private Box BoxOf(int level, int x, int y, int z)
        {
            var size = _fine * (1 << (Levels - level));
            return new Box(_origin.X + x * size - _pad, _origin.Y + y * size - _pad, _origin.Z + z * size - _pad,
                _origin.X + (x + 1) * size + _pad, _origin.Y + (y + 1) * size + _pad, _origin.Z + (z + 1) * size + _pad);
        }

        /// <summary>
        /// The walk of <see cref="BspSphereQuery.Overlaps"/> below one node over a box, the same decisions in the same
        /// order: true when it reaches a solid leaf with its centre check on for every centre under the guards open
        /// around it; what it cannot decide goes to <see cref="_scratch"/> as guards over blocks, polygons, or the
        /// node itself where its children's centre checks would depend on the centre's side of its plane.
        /// </summary>
        private bool Visit(int index, bool centreCheck, in Box box)
        {
            var node = _nodes[index];
            var sphere = node.IsLeaf && node.ListedPolygonCount == 0 ? Tri.False : SphereHits(node.SphereCenter, node.SphereRadius, box);
            if (node.IsLeaf)
            {
                if (node.ListedPolygonCount == 0) return false;
                if (centreCheck && node.Solid) return true;
                if (sphere == Tri.False) return false;
                var leafGuard = sphere == Tri.Mixed ? Open(index << 2 | SphereGuard) : -1;
                for (var k = 0; k < node.PolygonCount; k++)
                    if (!PolygonSkipped(node.PolygonStart + k, box)) _scratch.Add((node.PolygonStart + k) << 2 | PolygonTag);
                if (leafGuard >= 0) Close(leafGuard, false);
                return false;
            }
            if (sphere == Tri.False) return false;
            var (min, max) = PlaneRange(node.Normal, node.D, box);
            var positive = Compare(min, max, _reach, atLeast: true);
            var negative = Compare(min, max, -_reach, atLeast: false);
            var below = Compare(min, max, 0.0, atLeast: true) switch { Tri.True => Tri.False, Tri.False => Tri.True, _ => Tri.Mixed };
            // Guards carry the pushes; the children's centre checks must come out the same wherever they are pushed,
            // which needs the centre's side settled when the middle band (both children) is reachable with the check on.
            var middle = positive != Tri.True && negative != Tri.True;
            if ((_reach <= 0 && (positive == Tri.Mixed || negative == Tri.Mixed)) || (centreCheck && middle && below == Tri.Mixed))
            {
                _scratch.Add((index << 1 | (centreCheck ? 1 : 0)) << 2 | NodeTag);
                return false;
            }
            var pushPos = Or(positive, Not(negative));
            var pushNeg = Not(positive);
            var posCheck = centreCheck && (positive == Tri.True || below == Tri.False);
            var negCheck = centreCheck && (negative == Tri.True || below == Tri.True);
            var nodeGuard = sphere == Tri.Mixed ? Open(index << 2 | SphereGuard) : -1;
            var blocks = Branch(pushPos, node.Pos, posCheck, index << 2 | PushesPosGuard, box)
                || Branch(pushNeg, node.Neg, negCheck, index << 2 | PushesNegGuard, box);
            if (nodeGuard < 0) return blocks;
            Close(nodeGuard, blocks);
            return false;
        }

        /// <summary>One child as the walk pushes it: always, never, or behind its push guard.</summary>
        private bool Branch(Tri pushed, int child, bool centreCheck, int guard, in Box box)
        {
            if (pushed == Tri.False || child < 0) return false;
            if (pushed == Tri.True) return Visit(child, centreCheck, box);
            var mark = Open(guard);
            Close(mark, Visit(child, centreCheck, box));
            return false;
        }

        /// <summary>True when LeafTouches rejects the entry for every centre of the box, by its plane or by its bounding sphere.</summary>
        private bool PolygonSkipped(int entry, in Box box)
        {
            var plane = _planes[entry];
            var (min, max) = PlaneRange(new Vector3(plane.X, plane.Y, plane.Z), plane.W, box);
            var nearest = min > 0 ? min : max < 0 ? -max : 0.0;
            if (nearest > _reach) return true;
            var sphere = _spheres[entry];
            var sum = sphere.W + _radius;
            var (lo, _) = DistanceSquaredRange(new Vector3(sphere.X, sphere.Y, sphere.Z), box);
            return lo * (1 - SquareSlack) - Tiny > (double)sum * sum * (1 + SquareSlack);
        }

        /// <summary>NodeSphereHits over the box: |Δ|² &lt; (R + r)².</summary>
        private Tri SphereHits(Vector3 center, float radius, in Box box)
        {
            var sum = radius + _radius;
            var limit = (double)sum * sum;
            var (lo, hi) = DistanceSquaredRange(center, box);
            if (!(hi < Huge)) return Tri.Mixed;
            if (hi * (1 + SquareSlack) + Tiny < limit * (1 - SquareSlack)) return Tri.True;
            if (lo * (1 - SquareSlack) - Tiny >= limit * (1 + SquareSlack)) return Tri.False;
            return Tri.Mixed;
        }

        /// <summary>BroadPhaseHits over the box: |Δ|² − (R + r)² &lt; ε, the subtraction's rounding bounded too.</summary>
        private Tri BroadPhase(in CompiledBspNode root, in Box box)
        {
            var sum = root.SphereRadius + _radius;
            if (float.IsPositiveInfinity(sum * sum)) return Tri.True;
            var limit = (double)sum * sum;
            var (lo, hi) = DistanceSquaredRange(root.SphereCenter, box);
            if (!(hi < Huge)) return Tri.Mixed;
            var upper = hi * (1 + SquareSlack) + Tiny - limit * (1 - SquareSlack);
            if (upper + Math.Abs(upper) * 1e-6 + Tiny < PhysicsEpsilon.Value) return Tri.True;
            var lower = lo * (1 - SquareSlack) - Tiny - limit * (1 + SquareSlack);
            if (lower - Math.Abs(lower) * 1e-6 - Tiny >= PhysicsEpsilon.Value) return Tri.False;
            return Tri.Mixed;
        }

        /// <summary>dist ≥ value (atLeast) or dist ≤ value over the range of dist.</summary>
        private static Tri Compare(double min, double max, double value, bool atLeast)
        {
            if (atLeast) return min >= value ? Tri.True : max < value ? Tri.False : Tri.Mixed;
            return max <= value ? Tri.True : min > value ? Tri.False : Tri.Mixed;
        }

        /// <summary>
        /// The range of dot(n, c) + d over the box, widened by a bound on the float evaluation's rounding (a few ulps
        /// of the largest term); unbounded when a term could overflow a float.
        /// </summary>
        private static (double Min, double Max) PlaneRange(Vector3 n, float d, in Box box)
        {
            double min = d, max = d, scale = Math.Abs((double)d);
            Term(n.X, box.LoX, box.HiX, ref min, ref max, ref scale);
            Term(n.Y, box.LoY, box.HiY, ref min, ref max, ref scale);
            Term(n.Z, box.LoZ, box.HiZ, ref min, ref max, ref scale);
            if (!(scale < Huge)) return (double.NegativeInfinity, double.PositiveInfinity);
            var slack = 1e-6 * scale + Tiny;
            return (min - slack, max + slack);
        }

        private static void Term(double k, double lo, double hi, ref double min, ref double max, ref double scale)
        {
            min += k >= 0 ? k * lo : k * hi;
            max += k >= 0 ? k * hi : k * lo;
            scale += Math.Abs(k) * Math.Max(Math.Abs(lo), Math.Abs(hi));
        }

        /// <summary>The least and greatest squared distance from a point to the box.</summary>
        private static (double Lo, double Hi) DistanceSquaredRange(Vector3 p, in Box box)
        {
            double lo = 0, hi = 0;
            Axis(p.X, box.LoX, box.HiX, ref lo, ref hi);
            Axis(p.Y, box.LoY, box.HiY, ref lo, ref hi);
            Axis(p.Z, box.LoZ, box.HiZ, ref lo, ref hi);
            return (lo, hi);
        }

        private static void Axis(double p, double lo, double hi, ref double near, ref double far)
        {
            var gap = p < lo ? lo - p : p > hi ? p - hi : 0.0;
            var reach = Math.Max(Math.Abs(p - lo), Math.Abs(hi - p));
            near += gap * gap;
            far += reach * reach;
        }
    }
}
