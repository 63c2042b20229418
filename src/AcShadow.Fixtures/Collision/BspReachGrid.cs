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

    private readonly BspSphereQuery _tree;
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
        Radius = radius;
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
        return BspBoxWalk.Run(_tree, frontier, guarded, center, Radius);
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
        return VoxelOctree.Code(_cells, (int)fx, (int)fy, (int)fz, _top, _top, Levels);
    }

    internal static bool IsClear(int code) => code == ClearCode;

    internal static bool IsBlocked(int code) => code == BlockedCode;

    internal static bool IsOutside(int code) => code == OutsideCode;

    /// <summary>
    /// A cell's frontier (nodes, polygons, guards over blocks, true: <see cref="BspBoxWalk.IsNodeItem"/>, <see cref="BspBoxWalk.IsPolygonItem"/>,
    /// <see cref="BspBoxWalk.IsGuard"/>; anything else blocks), and whether the root's broad phase must pass first; a guarded
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

    /// <summary>
    /// A cell waiting to be split: where its code is, its place at its level, and the frontier its children start
    /// from (null: the walk from the root; guarded: the root's broad phase still undecided).
    /// </summary>
    private sealed record Pending(int Slot, int Level, int X, int Y, int Z, int[]? Items, bool Guarded, long Cost);

    /// <summary>The build: deterministic (no threads, fixed orders), so the same tree always gives the same grid.</summary>
    private sealed class Builder
    {
        private readonly BspBoxWalk _walk;
        private readonly Vector3 _origin;
        private readonly double _fine;
        private readonly double _pad;
        private readonly int _top;
        private readonly List<int> _cells = [];
        private readonly List<int> _items = [];
        private readonly Dictionary<string, int> _frontiers = new(StringComparer.Ordinal);

        public Builder(BspSphereQuery tree, float radius, Vector3 origin, float inverseFine, int top)
        {
            // A tree's index holds at most 4,096 cells: programs written per side would outgrow it, a walk from the node does not.
            _walk = new BspBoxWalk(tree, radius, splitSides: false);
            _origin = origin;
            _fine = 1.0 / inverseFine;
            _top = top;
            // Every float centre whose (c − origin) · inverse floors to a voxel lies within a few ulps of the grid's
            // extent of the voxel's nominal box.
            var extent = _fine * (top << Levels);
            _pad = 1e-6 * (extent + Math.Abs(origin.X) + Math.Abs(origin.Y) + Math.Abs(origin.Z)) + 1e-6;
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
            return (VoxelOctree.DepthFirst([.. _cells], _top * _top * _top), [.. _items]);
        }

        /// <summary>Classifies one cell from its parent's frontier, writes its code, and queues it for splitting when its frontier is worth it.</summary>
        private void Settle(Pending cell, List<Pending> pending)
        {
            var settled = _walk.Settle(BoxOf(cell.Level, cell.X, cell.Y, cell.Z), cell.Items, cell.Guarded);
            switch (settled.Outcome)
            {
                case BspBoxWalk.Outcome.Clear:
                    _cells[cell.Slot] = ClearCode;
                    return;
                case BspBoxWalk.Outcome.Blocked:
                    _cells[cell.Slot] = settled.Guarded ? GuardedBlockedCode : BlockedCode;
                    return;
            }
            _cells[cell.Slot] = FrontierBase + Store(settled.Items, settled.Guarded);
            if (cell.Level < Levels && settled.Cost >= SplitCost) pending.Add(cell with { Items = settled.Items, Guarded = settled.Guarded, Cost = settled.Cost });
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

        private CentreBox BoxOf(int level, int x, int y, int z)
        {
            var size = _fine * (1 << (Levels - level));
            return new CentreBox(_origin.X + x * size - _pad, _origin.Y + y * size - _pad, _origin.Z + z * size - _pad,
                _origin.X + (x + 1) * size + _pad, _origin.Y + (y + 1) * size + _pad, _origin.Z + (z + 1) * size + _pad);
        }
    }
}
