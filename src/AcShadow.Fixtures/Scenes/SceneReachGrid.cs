using System.Numerics;
using System.Runtime.InteropServices;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A whole scene decided ahead of time for one mover radius over the voxels of a landblock-frame grid: a compiled
/// scene (<see cref="SceneQuery"/>) asks one voxel instead of the land cells, the broad phases and the turns. Each
/// voxel is Clear (no entry blocks any centre in it), Blocked (some entry blocks every centre in it) or a frontier:
/// the entries left open there, each with what the walk leaves open of its tree over the voxel
/// (<see cref="BspBoxWalk"/>), asked at the centre by the same float operations the entry's own test makes.
/// <list type="bullet">
/// <item>A voxel's box is padded past every float centre mapped to it, then carried through the entry's turns (the
/// object's frame and the part's, or the cell's: <see cref="CentreBox.Turned"/>), each widened by its rounding, so a
/// tree's decision over the turned box holds for every centre the entry's test can compute there.</item>
/// <item>An entry's broad phases (the object's sphere, the part's reach, a cell's root sphere) are decided over the
/// box too: an entry they refuse for the whole box is dropped, one they pass for the whole box is asked without them,
/// otherwise they are asked first, as the entry asks them. A voxel is Blocked only when an entry blocks with its
/// broad phases passing for the whole box.</item>
/// <item>Entries that are not one posed tree (spheres, cylinders, boxes, hulls, several shapes together) are listed
/// whenever their broad phases may pass, and asked whole.</item>
/// </list>
/// The answer is the partitioned walk's (any entry blocks), bit for bit. An octree under a coarse grid: empty
/// space settles in large cells, the budget goes to the costliest frontiers. A centre outside the grid is beyond every
/// entry's broad phase; entries without a finite one are asked at every position. Immutable after the build.
/// </summary>
internal sealed class SceneReachGrid
{
    // A cell's code: Clear, Blocked, a frontier (FrontierBase + its offset in _frontiers: the item count, then per item
    // entry << 1 | gated and the offset of its program in _programs, −1: ask the entry whole), or minus the index of
    // its eight children in _cells.
    private const int ClearCode = 0, BlockedCode = 1, FrontierBase = 2;
    /// <summary>Octree levels under a top cell: the finest voxel is a top cell's edge / 32.</summary>
    private const int Levels = 5;
    /// <summary>At most this many top cells; a wider scene gets larger ones.</summary>
    private const int MaxTopCells = 1 << 18;
    /// <summary>A frontier cheaper than this (turns, broad phases, nodes and polygons) is not split further.</summary>
    private const int SplitCost = 4;
    /// <summary>A broad-phase sphere wider than this (metres) makes its entry one asked everywhere.</summary>
    private const float MaxGate = 2000f;

    private readonly PlacedQuery[] _objects;
    private readonly SceneCell[] _cells;
    private readonly CellReach[] _cellReach;
    private readonly Target?[] _targets;
    private readonly int[] _always;
    private readonly Vector3 _origin;
    private readonly float _inverseFine;
    private readonly int _topX, _topY, _topZ, _fineX, _fineY, _fineZ;
    private readonly int[] _codes;
    private readonly int[] _frontiers;
    private readonly int[] _programs;

    public float Radius { get; }

    /// <summary>The entries asked at every position, before the voxel (no finite broad phase).</summary>
    internal IReadOnlyList<int> Always => _always;

    /// <summary>What the grid holds, in bytes.</summary>
    public long Bytes => 4L * (_codes.Length + _frontiers.Length + _programs.Length);

    /// <summary>A tree entry: the tree, the part's pose (an object's part) or null (a cell), and the walk over boxes at its radius.</summary>
    private sealed record Target(BspSphereQuery Tree, PartPose? Pose, ClientFrameMatrix Matrix, BspBoxWalk Walk);

    private SceneReachGrid(PlacedQuery[] objects, SceneCell[] cells, CellReach[] cellReach, Target?[] targets, int[] always, float radius,
        Vector3 origin, float inverseFine, (int X, int Y, int Z) top, int[] codes, int[] frontiers, int[] programs)
    {
        (_objects, _cells, _cellReach, _targets, _always) = (objects, cells, cellReach, targets, always);
        Radius = radius;
        _origin = origin;
        _inverseFine = inverseFine;
        (_topX, _topY, _topZ) = top;
        (_fineX, _fineY, _fineZ) = (top.X << Levels, top.Y << Levels, top.Z << Levels);
        (_codes, _frontiers, _programs) = (codes, frontiers, programs);
    }

    /// <summary>
    /// The grid of a scene's entries for one mover radius, holding at most <paramref name="cellBudget"/> cell codes, and
    /// programs costing more than 16 only while its programs hold fewer than <paramref name="programBudget"/> ints (past
    /// it such entries are asked whole); null for an unusable radius.
    /// </summary>
    public static SceneReachGrid? Build(PlacedQuery[] objects, SceneCell[] cells, CellReach[] cellReach, float radius, int cellBudget = 1 << 19,
        int programBudget = 1 << 22) =>
        SphereBounds.IsValidProbe(Vector3.Zero, radius) && radius > 0f ? new Builder(objects, cells, cellReach, radius, cellBudget, programBudget).Run() : null;

    /// <summary>Does a sphere of <see cref="Radius"/> at this (valid) landblock-relative centre touch any entry?</summary>
    public bool Overlaps(Vector3 center)
    {
        foreach (var e in _always)
            if (AskWhole(e, center)) return true;
        var code = Code(center);
        if (code == ClearCode) return false;
        if (code == BlockedCode) return true;
        var at = code - FrontierBase;
        var count = _frontiers[at++];
        object? frame = null;
        var local = Vector3.Zero;
        var localRadius = 0f;
        for (var k = 0; k < count; k++, at += 2)
        {
            var head = _frontiers[at];
            var entry = head >> 1;
            var program = _frontiers[at + 1];
            if ((head & 1) != 0 && !Gate(entry, center)) continue;
            if (entry < _objects.Length && !ReferenceEquals(_objects[entry].FrameKey, frame))
            {
                // The parts of one object share the turn into its frame: the same float operations each time.
                (local, localRadius) = _objects[entry].ToEntity(center, Radius);
                frame = _objects[entry].FrameKey;
            }
            if (program < 0)
            {
                // Asked whole behind its broad phases, which the voxel settled (passing over all of it) or which were
                // asked just above: the entry's own test from the turn on.
                if (entry < _objects.Length ? _objects[entry].EntityQuery.Overlaps(local, localRadius) : _cells[entry - _objects.Length].Query.Overlaps(center, Radius))
                    return true;
                continue;
            }
            var target = _targets[entry]!;
            Vector3 turned;
            float turnedRadius;
            if (entry < _objects.Length) (turned, turnedRadius) = target.Pose!.Value.ToLocal(target.Matrix, local, localRadius);
            else (turned, turnedRadius) = (target.Matrix.GlobalToLocal(center), Radius);
            var header = _programs[program];
            if (BspBoxWalk.Run(target.Tree, _programs.AsSpan(program + 1, header >> 1), (header & 1) != 0, turned, turnedRadius)) return true;
        }
        return false;
    }

    /// <summary>
    /// What a centre's voxel holds, for counting a query's path: Clear, Blocked, or the frontier's items (entry, gated,
    /// the program and its guard: null program, the entry asked whole).
    /// </summary>
    internal (bool Clear, bool Blocked, (int Entry, bool Gated, int[]? Program, bool Guarded)[] Items) At(Vector3 center)
    {
        var code = Code(center);
        if (code == ClearCode) return (true, false, []);
        if (code == BlockedCode) return (false, true, []);
        var at = code - FrontierBase;
        var items = new (int, bool, int[]?, bool)[_frontiers[at++]];
        for (var k = 0; k < items.Length; k++, at += 2)
        {
            var program = _frontiers[at + 1];
            var header = program < 0 ? 0 : _programs[program];
            items[k] = (_frontiers[at] >> 1, (_frontiers[at] & 1) != 0, program < 0 ? null : _programs.AsSpan(program + 1, header >> 1).ToArray(), (header & 1) != 0);
        }
        return (false, false, items);
    }

    /// <summary>How many cells of each kind the grid holds (octree leaves of any size), and how many top cells it has.</summary>
    internal (int Clear, int Blocked, int Frontier, int Top) StateCounts()
    {
        int clear = 0, blocked = 0, frontier = 0;
        foreach (var code in _codes)
        {
            if (code < 0) continue;
            if (code == ClearCode) clear++;
            else if (code == BlockedCode) blocked++;
            else frontier++;
        }
        return (clear, blocked, frontier, _topX * _topY * _topZ);
    }

    /// <summary>The entry's broad phases as its own test asks them: an object's whole sphere, then its (part's) bound; a cell's root sphere.</summary>
    private bool Gate(int entry, Vector3 center)
    {
        if (entry >= _objects.Length) return _cellReach[entry - _objects.Length].Reaches(center, Radius);
        var o = _objects[entry];
        return (o.Whole is not { } whole || whole.Near(center, Radius)) && o.Near(center, Radius);
    }

    /// <summary>The entry's own test, whole: what the partitioned walk asks of it.</summary>
    private bool AskWhole(int entry, Vector3 center)
    {
        if (entry >= _objects.Length)
        {
            var cell = entry - _objects.Length;
            return _cellReach[cell].Reaches(center, Radius) && _cells[cell].Query.Overlaps(center, Radius);
        }
        var o = _objects[entry];
        if (o.Whole is { } whole && !whole.Near(center, Radius)) return false;
        return o.Overlaps(center, Radius);
    }

    private int Code(Vector3 center)
    {
        var fx = (center.X - _origin.X) * _inverseFine;
        var fy = (center.Y - _origin.Y) * _inverseFine;
        var fz = (center.Z - _origin.Z) * _inverseFine;
        if (!(fx >= 0f && fx < _fineX && fy >= 0f && fy < _fineY && fz >= 0f && fz < _fineZ)) return ClearCode;
        return VoxelOctree.Code(_codes, (int)fx, (int)fy, (int)fz, _topY, _topZ, Levels);
    }

    /// <summary>One entry open over a cell: its program (null: asked whole) and guard, and whether its broad phases are asked first.</summary>
    private readonly record struct Open(int Entry, bool Gated, int Program, long Cost);

    /// <summary>A cell waiting to be split: where its code is, its place at its level, and its frontier (offset in the stored frontiers) its children start from.</summary>
    private readonly record struct Pending(int Slot, int Level, int X, int Y, int Z, int Frontier, long Cost);

    /// <summary>The build: deterministic (no threads, fixed orders), so the same scene always gives the same grid.</summary>
    private sealed class Builder
    {
        /// <summary>
        /// A program that would cost more than this is not stored: the entry is asked whole, through its tree's own index.
        /// That index's voxels are coarser and keep a node whole where the centre's side decides its children, so up to
        /// here the program is the cheaper ask (16 → 32: about 5 % off the compiled scene on the scale dat's 0x0000); past
        /// it, storing more cost memory for no measured gain (64: 0.95 of 16's time, 32: 0.93-0.95, each measured against
        /// 16; a 45.7 MB grid against 17.6; docs/performance.md, 2026-12-03 sixth session).
        /// </summary>
        private const long LongProgram = 32;

        /// <summary>
        /// A program up to this cost is always stored (the bound before 2026-12-03's sixth session); a costlier one only
        /// while the programs hold fewer ints than the build's program budget (16 MiB by default), so a denser scene than
        /// any measured cannot grow the grid without bound through them.
        /// </summary>
        private const long ShortProgram = 16;

        /// <summary>What asking an entry whole is counted at, for the split order: two turns and a short walk.</summary>
        private const long WholeCost = 8;

        private readonly PlacedQuery[] _objects;
        private readonly SceneCell[] _cells;
        private readonly CellReach[] _cellReach;
        private readonly float _radius;
        private readonly int _budget;
        private readonly int _programBudget;
        private readonly Target?[] _targets;
        private readonly List<int> _always = [];
        private readonly List<int> _codes;
        private readonly List<int> _frontiers = [];
        private readonly List<int> _programs = [];
        private readonly Dictionary<ulong, int> _frontierIndex = [];
        private readonly Dictionary<ulong, int> _programIndex = [];
        private readonly List<int> _scratch = [];
        private readonly List<Open> _open = [];
        private readonly List<Open> _parents = [];
        private Vector3 _origin;
        private double _fine, _pad;
        private int _topX, _topY, _topZ;

        public Builder(PlacedQuery[] objects, SceneCell[] cells, CellReach[] cellReach, float radius, int budget, int programBudget)
        {
            (_objects, _cells, _cellReach, _radius, _budget, _programBudget) = (objects, cells, cellReach, radius, budget, programBudget);
            _codes = new List<int>(Math.Min(budget, 1 << 16));
            var walks = new Dictionary<(BspSphereQuery, float), BspBoxWalk>();
            _targets = new Target?[objects.Length + cells.Length];
            for (var i = 0; i < objects.Length; i++)
            {
                if (objects[i].EntityQuery is not PosedQuery { RefusesByReach: false } posed || TreeOf(posed.PartQuery) is not { } tree) continue;
                var partRadius = posed.Pose.ToLocal(Vector3.Zero, radius).Radius;
                _targets[i] = new Target(tree, posed.Pose, posed.Pose.Matrix, Walk(tree, partRadius));
            }
            for (var i = 0; i < cells.Length; i++)
                if (cells[i].Query is CellOverlapQuery cell)
                    _targets[objects.Length + i] = new Target(cell.Tree, null, cell.Frame, Walk(cell.Tree, radius));

            BspBoxWalk Walk(BspSphereQuery tree, float r)
            {
                if (!walks.TryGetValue((tree, r), out var walk)) walks[(tree, r)] = walk = new BspBoxWalk(tree, r);
                return walk;
            }
        }

        private static BspSphereQuery? TreeOf(ISphereOverlap query) => query switch
        {
            BspSphereQuery tree => tree,
            IndexedBspQuery indexed => indexed.Tree,
            _ => null,
        };

        public SceneReachGrid Run()
        {
            // Each entry's broad phase as a box (the gate it must pass), or asked everywhere.
            var gates = new (double LoX, double LoY, double LoZ, double HiX, double HiY, double HiZ)?[_targets.Length];
            double x0 = double.MaxValue, y0 = double.MaxValue, z0 = double.MaxValue, x1 = double.MinValue, y1 = double.MinValue, z1 = double.MinValue;
            for (var e = 0; e < _targets.Length; e++)
            {
                var (center, distance) = GateSphere(e);
                if (!(Vec.IsFinite(center) && float.IsFinite(distance) && distance >= 0f && distance <= MaxGate && center.Length() < 1e6f))
                {
                    _always.Add(e);
                    continue;
                }
                var d = distance * 1.0001 + 1e-3 * (1 + center.Length()) + 0.01;
                gates[e] = (center.X - d, center.Y - d, center.Z - d, center.X + d, center.Y + d, center.Z + d);
                (x0, y0, z0) = (Math.Min(x0, center.X - d), Math.Min(y0, center.Y - d), Math.Min(z0, center.Z - d));
                (x1, y1, z1) = (Math.Max(x1, center.X + d), Math.Max(y1, center.Y + d), Math.Max(z1, center.Z + d));
            }
            if (x0 > x1) return Result(Vector3.Zero, 1f, (0, 0, 0));
            // The finest voxel a quarter of the radius; the top cells as many as the limit allows, larger if needed.
            var fine = _radius / 4.0;
            var volume = (x1 - x0) * (y1 - y0) * (z1 - z0);
            while (volume / Math.Pow(fine * (1 << Levels), 3) > MaxTopCells) fine *= 2;
            var inverseFine = (float)(1.0 / fine);
            _fine = 1.0 / inverseFine;
            var topEdge = _fine * (1 << Levels);
            _origin = new Vector3((float)x0, (float)y0, (float)z0);
            _topX = Math.Max(1, (int)Math.Ceiling((x1 - _origin.X) / topEdge));
            _topY = Math.Max(1, (int)Math.Ceiling((y1 - _origin.Y) / topEdge));
            _topZ = Math.Max(1, (int)Math.Ceiling((z1 - _origin.Z) / topEdge));
            _pad = 1e-6 * (topEdge * Math.Max(_topX, Math.Max(_topY, _topZ)) + Math.Abs(_origin.X) + Math.Abs(_origin.Y) + Math.Abs(_origin.Z)) + 1e-6;
            // Each top cell's candidates: the entries whose gate box meets it.
            var candidates = new List<int>?[_topX * _topY * _topZ];
            for (var e = 0; e < gates.Length; e++)
            {
                if (gates[e] is not { } g) continue;
                int ax = Top(g.LoX, _origin.X, _topX), bx = Top(g.HiX, _origin.X, _topX);
                int ay = Top(g.LoY, _origin.Y, _topY), by = Top(g.HiY, _origin.Y, _topY);
                int az = Top(g.LoZ, _origin.Z, _topZ), bz = Top(g.HiZ, _origin.Z, _topZ);
                for (var x = ax; x <= bx; x++)
                    for (var y = ay; y <= by; y++)
                        for (var z = az; z <= bz; z++)
                            (candidates[(x * _topY + y) * _topZ + z] ??= []).Add(e);
            }
            var pending = new List<Pending>();
            for (var x = 0; x < _topX; x++)
                for (var y = 0; y < _topY; y++)
                    for (var z = 0; z < _topZ; z++)
                    {
                        _codes.Add(ClearCode);
                        if (candidates[(x * _topY + y) * _topZ + z] is not { } list) continue;
                        _parents.Clear();
                        foreach (var e in list) _parents.Add(new Open(e, true, -1, 0));
                        Settle(new Pending(_codes.Count - 1, 0, x, y, z, -1, 0), pending);
                    }
            // Level by level, the costliest frontiers first, while the budget lasts.
            for (var level = 0; level < Levels && pending.Count > 0; level++)
            {
                // Every pending cell is at this level (a cell is queued one level below the cell it splits).
                var splitting = pending.ToArray();
                pending.Clear();
                Array.Sort(splitting, (a, b) => a.Cost != b.Cost ? b.Cost.CompareTo(a.Cost) : a.Slot.CompareTo(b.Slot));
                foreach (var cell in splitting)
                {
                    if (_codes.Count + 8 > _budget) break;
                    var first = _codes.Count;
                    _codes[cell.Slot] = -first;
                    for (var k = 0; k < 8; k++) _codes.Add(ClearCode);
                    for (var k = 0; k < 8; k++)
                    {
                        Parents(cell.Frontier);
                        Settle(new Pending(first + k, level + 1, cell.X * 2 + (k & 1), cell.Y * 2 + (k >> 1 & 1), cell.Z * 2 + (k >> 2 & 1), -1, 0), pending);
                    }
                }
            }
            return Result(_origin, inverseFine, (_topX, _topY, _topZ));
        }

        private SceneReachGrid Result(Vector3 origin, float inverseFine, (int X, int Y, int Z) top) =>
            new(_objects, _cells, _cellReach, _targets, [.. _always], _radius, origin, inverseFine, top,
                VoxelOctree.DepthFirst([.. _codes], top.X * top.Y * top.Z), [.. _frontiers], [.. _programs]);

        private int Top(double v, float origin, int count) => Math.Clamp((int)Math.Floor((v - origin) / (_fine * (1 << Levels))), 0, count - 1);

        /// <summary>The sphere an entry's first broad phase passes within (the part's or object's bound, the cell's root sphere).</summary>
        private (Vector3 Center, float Distance) GateSphere(int e)
        {
            if (e >= _objects.Length)
            {
                var reach = _cellReach[e - _objects.Length];
                return reach.Always ? (Vector3.Zero, float.PositiveInfinity) : (reach.Center, reach.Radius + _radius * 1.001f);
            }
            var o = _objects[e];
            return (o.LandblockBound.Center, o.NearDistance(_radius));
        }

        /// <summary>A stored frontier's entries, as the open entries its children start from.</summary>
        private void Parents(int frontier)
        {
            _parents.Clear();
            var count = _frontiers[frontier];
            for (var k = 0; k < count; k++)
            {
                var head = _frontiers[frontier + 1 + 2 * k];
                _parents.Add(new Open(head >> 1, (head & 1) != 0, _frontiers[frontier + 2 + 2 * k], 0));
            }
        }

        /// <summary>Classifies one cell from its parent's open entries (<see cref="_parents"/>), writes its code, and queues it for splitting when its frontier is worth it.</summary>
        private void Settle(Pending cell, List<Pending> pending)
        {
            var box = BoxOf(cell.Level, cell.X, cell.Y, cell.Z);
            _open.Clear();
            long cost = 0;
            foreach (var parent in _parents)
            {
                var gate = parent.Gated ? GateOver(parent.Entry, box) : BoxDecision.True;
                if (gate == BoxDecision.False) continue;
                var gated = gate == BoxDecision.Mixed;
                var target = _targets[parent.Entry];
                var local = target is null ? default : LocalBox(parent.Entry, target, box);
                if (target is null || !local.IsUsable)
                {
                    _open.Add(new Open(parent.Entry, gated, -1, WholeCost));
                    cost += WholeCost;
                    continue;
                }
                var settled = parent.Program < 0
                    ? target.Walk.Settle(local, true, [], true, copy: false)
                    : target.Walk.Settle(local, false, ProgramItems(parent.Program, out var parentGuarded), parentGuarded, copy: false);
                if (settled.Outcome == BspBoxWalk.Outcome.Clear) continue;
                if (settled.Outcome == BspBoxWalk.Outcome.Blocked && !settled.Guarded && !gated)
                {
                    _codes[cell.Slot] = BlockedCode;
                    return;
                }
                // Blocked behind a broad phase: the program that blocks once it passes. A long program (a cell the budget
                // left large) is not kept: the entry is asked whole there, through its tree's own voxel index.
                var program = settled.Outcome == BspBoxWalk.Outcome.Blocked ? Program(BspBoxWalk.Blocks, settled.Guarded)
                    : settled.Cost > LongProgram || (settled.Cost > ShortProgram && _programs.Count >= _programBudget) ? -1
                    : Program(target.Walk.LastFrontier, settled.Guarded);
                var open = new Open(parent.Entry, gated, program, (gated ? 1 : 0) + 2 + settled.Cost);
                _open.Add(open);
                cost += open.Cost;
            }
            if (_open.Count == 0)
            {
                _codes[cell.Slot] = ClearCode;
                return;
            }
            var frontier = Store(_open);
            _codes[cell.Slot] = FrontierBase + frontier;
            if (cell.Level < Levels && cost >= SplitCost) pending.Add(cell with { Frontier = frontier, Cost = cost });
        }

        private BoxDecision GateOver(int entry, in CentreBox box)
        {
            if (entry >= _objects.Length) return _cellReach[entry - _objects.Length].ReachesOver(box, _radius);
            var o = _objects[entry];
            var whole = o.Whole is { } w ? w.NearOver(box, _radius) : BoxDecision.True;
            if (whole == BoxDecision.False) return BoxDecision.False;
            var own = o.NearOver(box, _radius);
            return own == BoxDecision.False ? BoxDecision.False : whole == BoxDecision.True && own == BoxDecision.True ? BoxDecision.True : BoxDecision.Mixed;
        }

        /// <summary>The box of centres the entry's tree is asked at, for landblock centres in <paramref name="box"/>: the object's turn, then the part's; or the cell's.</summary>
        private CentreBox LocalBox(int entry, Target target, in CentreBox box)
        {
            if (target.Pose is not { } pose) return box.Turned(target.Matrix);
            var o = _objects[entry];
            return box.Turned(o.Matrix).Scaled(1f / o.Frame.Scale).Turned(target.Matrix).Scaled(1f / pose.Scale);
        }

        /// <summary>A stored program's items and guard.</summary>
        private ReadOnlySpan<int> ProgramItems(int offset, out bool guarded)
        {
            var programs = CollectionsMarshal.AsSpan(_programs);
            guarded = (programs[offset] & 1) != 0;
            return programs.Slice(offset + 1, programs[offset] >> 1);
        }

        /// <summary>A frontier: each entry and its program, stored once however many voxels share it.</summary>
        private int Store(List<Open> entries)
        {
            _scratch.Clear();
            _scratch.Add(entries.Count);
            foreach (var o in entries)
            {
                _scratch.Add(o.Entry << 1 | (o.Gated ? 1 : 0));
                _scratch.Add(o.Program);
            }
            return Intern(_frontiers, _frontierIndex, CollectionsMarshal.AsSpan(_scratch));
        }

        private int Program(ReadOnlySpan<int> items, bool guarded)
        {
            _scratch.Clear();
            _scratch.Add(items.Length << 1 | (guarded ? 1 : 0));
            foreach (var item in items) _scratch.Add(item);
            return Intern(_programs, _programIndex, CollectionsMarshal.AsSpan(_scratch));
        }

        /// <summary>
        /// The offset of <paramref name="content"/> in <paramref name="store"/>, appended unless an equal run is there
        /// already (found by a hash of its ints and compared in full; a hash shared by a different run stores a copy).
        /// </summary>
        private static int Intern(List<int> store, Dictionary<ulong, int> index, ReadOnlySpan<int> content)
        {
            var hash = 14695981039346656037UL;
            foreach (var v in content) hash = (hash ^ (uint)v) * 1099511628211UL;
            if (index.TryGetValue(hash, out var known) && known + content.Length <= store.Count
                && CollectionsMarshal.AsSpan(store).Slice(known, content.Length).SequenceEqual(content))
                return known;
            var offset = store.Count;
            foreach (var v in content) store.Add(v);
            index.TryAdd(hash, offset);
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
