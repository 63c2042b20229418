using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// <see cref="BspSphereQuery.Overlaps"/> for one radius run over a box of centres (<see cref="CentreBox"/>) with
/// interval arithmetic: what the walk decides the same way for every centre of the box is taken, what it does not is
/// left as a frontier, a small program (<see cref="Run"/>) of guards over blocks (the node's sphere test or its push
/// of one child: the walk's own float test), single listed polygons, and nodes walked from there where the centre
/// check would depend on the centre's side. The walk's answer is an OR over what it reaches and a reached node's
/// subtree answers independently of the rest, so running the frontier at a centre of the box gives the walk's answer
/// bit for bit, for any tree however malformed. Every comparison is padded by a bound on the float rounding of the
/// walk's evaluation; a decision that could go either way stays open. <see cref="BspReachGrid"/> settles the voxels of
/// a part-local grid with it, <see cref="Scenes.SceneReachGrid"/> the voxels of a whole scene.
/// </summary>
internal sealed class BspBoxWalk
{
    // A frontier item: payload << 2 | tag. Node: payload node << 1 | centre check, walked from there. Polygon:
    // payload the listed-polygon entry. Guard: payload node << 3 | kind, then the length of the block it guards,
    // skipped when the guard fails. Tag 3: payload 0 blocks (True); payload entry + 1 is a plane item, a listed
    // polygon whose contact point lies inside it and whose bounding sphere is met over the whole box, so only its
    // plane distance is left to test.
    private const int NodeTag = 0, PolygonTag = 1, GuardTag = 2, TrueItem = 3;
    // Guard kinds: the node's sphere test, its push of either child, and the centre's side of its plane (dist < 0 or not).
    private const int SphereGuard = 0, PushesPosGuard = 1, PushesNegGuard = 2, BelowGuard = 3, NotBelowGuard = 4;



    /// <summary>Relative bound on the float rounding of a squared distance or of R + r squared, with room to spare.</summary>
    private const double SquareSlack = 4e-6;
    private const double Tiny = 1e-30;
    /// <summary>Past this magnitude a float evaluation may overflow: the decision is left to the walk.</summary>
    private const double Huge = 1e30;

    private readonly BspSphereQuery _tree;
    // The tree's own arrays, read in place: a walk per tree and radius, held while a grid is built, copies nothing.
    private ReadOnlySpan<CompiledBspNode> _nodes => _tree.Nodes;
    private ReadOnlySpan<Vector4> _planes => _tree.LeafPlanes;
    private ReadOnlySpan<Vector4> _spheres => _tree.LeafSpheres;
    private readonly float _radius;
    private readonly double _reach;
    private readonly long[] _subtreeCost;
    private readonly List<int> _scratch = [];

    /// <summary>What a box settles to: clear (no items), blocked, or a frontier; guarded: the root's broad phase is asked first.</summary>
    public enum Outcome { Clear, Blocked, Frontier }

    /// <param name="Outcome">Clear, blocked (behind the broad phase when guarded), or a frontier.</param>
    /// <param name="Items">The frontier's program (empty unless <see cref="Outcome.Frontier"/>).</param>
    /// <param name="Guarded">The root's broad phase is not decided over the box: asked before the items (a guarded block answers by it alone).</param>
    /// <param name="Cost">Nodes and polygons a walk of the frontier would look at, at most.</param>
    public readonly record struct Settled(Outcome Outcome, int[] Items, bool Guarded, long Cost);

    private readonly bool _splitSides;

    /// <param name="tree">The tree whose walk is run over boxes.</param>
    /// <param name="radius">The mover radius, in the tree's units.</param>
    /// <param name="splitSides">
    /// Write a node whose children's centre check depends on the centre's side as two side-guarded blocks (more to
    /// store, less to run: the scene's grid), instead of a walk from the node (a tree's own small index).
    /// </param>
    public BspBoxWalk(BspSphereQuery tree, float radius, bool splitSides = true)
    {
        _splitSides = splitSides;
        _tree = tree;
        _radius = radius;
        _reach = radius - PhysicsEpsilon.Value;
        _subtreeCost = new long[_nodes.Length];
        for (var i = _nodes.Length - 1; i >= 0; i--)
        {
            ref readonly var node = ref _nodes[i];
            _subtreeCost[i] = 1 + (node.IsLeaf ? node.PolygonCount
                : (node.Pos >= 0 ? _subtreeCost[node.Pos] : 0) + (node.Neg >= 0 ? _subtreeCost[node.Neg] : 0));
        }
    }

    /// <summary>A program that blocks (behind the broad phase when guarded): what a blocked box runs as a frontier.</summary>
    public static ReadOnlySpan<int> Blocks => [TrueItem];

    /// <summary>
    /// The walk over a box, from the root (<paramref name="parent"/> null: the broad phase and the whole tree) or
    /// from an enclosing box's frontier (a decision uniform over the enclosing box stays so over this one).
    /// </summary>
    public Settled Settle(in CentreBox box, int[]? parent = null, bool parentGuarded = true) =>
        Settle(box, parent is null, parent, parentGuarded);

    /// <summary>
    /// <see cref="Settle(in CentreBox, int[], bool)"/> from a stored program (<paramref name="fromRoot"/>: ignore it, walk from
    /// the root). Not <paramref name="copy"/>: the frontier is left in <see cref="LastFrontier"/> (until the next settle)
    /// instead of copied into <see cref="Settled.Items"/>, for a caller that stores it at once.
    /// </summary>
    public Settled Settle(in CentreBox box, bool fromRoot, ReadOnlySpan<int> parent, bool parentGuarded, bool copy = true)
    {
        if (_nodes.Length == 0) return new Settled(Outcome.Clear, [], false, 0);
        _scratch.Clear();
        var guarded = false;
        if (parentGuarded)
        {
            var broad = BroadPhase(_nodes[0], box);
            if (broad == BoxDecision.False) return new Settled(Outcome.Clear, [], false, 0);
            guarded = broad == BoxDecision.Mixed;
        }
        var blocked = fromRoot ? Visit(0, true, box) : Replay(parent, 0, parent.Length, box);
        if (blocked) return new Settled(Outcome.Blocked, [], guarded, guarded ? 1 : 0);
        if (_scratch.Count == 0) return new Settled(Outcome.Clear, [], false, 0);
        var frontier = LastFrontier;
        long cost = guarded ? 1 : 0;
        for (var i = 0; i < frontier.Length; i++)
        {
            cost += IsNodeItem(frontier[i], out var node, out _) ? _subtreeCost[node] : 1;
            if (IsGuard(frontier[i], out _)) i++;
        }
        return new Settled(Outcome.Frontier, copy ? frontier.ToArray() : [], guarded, cost);
    }

    /// <summary>The frontier the last <see cref="Settle(in CentreBox, bool, ReadOnlySpan{int}, bool, bool)"/> left (empty unless it was a frontier).</summary>
    public ReadOnlySpan<int> LastFrontier => System.Runtime.InteropServices.CollectionsMarshal.AsSpan(_scratch);

    /// <summary>
    /// A settled frontier at a centre of its box: <see cref="BspSphereQuery.Overlaps"/>'s answer there. Guarded: the
    /// root's broad phase first; a guarded frontier without items blocks when it passes.
    /// </summary>
    public static bool Run(BspSphereQuery tree, ReadOnlySpan<int> items, bool guarded, Vector3 center, float radius)
    {
        var nodes = tree.Nodes;
        if (guarded && !SphereBounds.BroadPhaseHits(nodes[0], center, radius)) return false;
        if (items.IsEmpty) return guarded;
        var reach = radius - PhysicsEpsilon.Value;
        for (var i = 0; i < items.Length;)
        {
            var item = items[i++];
            switch (item & 3)
            {
                case NodeTag:
                    if (tree.WalkFrom(item >> 3, (item & 4) != 0, center, radius, reach)) return true;
                    break;
                case PolygonTag:
                    if (tree.EntryTouches(item >> 2, center, radius, reach)) return true;
                    break;
                case GuardTag:
                    var length = items[i++];
                    if (!Passes(nodes, item >> 2, center, radius, reach)) i += length;
                    break;
                default:
                    if (item == TrueItem || tree.EntryReachesPlane((item >> 2) - 1, center, reach)) return true;
                    break;
            }
        }
        return false;
    }

    /// <summary>A guard as the walk decides it at this centre: the node's sphere test, or whether it pushes that child.</summary>
    internal static bool Passes(ReadOnlySpan<CompiledBspNode> nodes, int guard, Vector3 center, float radius, float reach)
    {
        ref readonly var node = ref nodes[guard >> 3];
        var kind = guard & 7;
        if (kind == SphereGuard) return SphereBounds.NodeSphereHits(node, center, radius);
        var dist = PolygonPlane.Dot(node.Normal, center) + node.D;
        return kind switch
        {
            PushesPosGuard => dist >= reach || !(dist <= -reach),
            PushesNegGuard => !(dist >= reach),
            BelowGuard => dist < 0f,
            _ => !(dist < 0f),
        };
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

    /// <summary>A plane item: a listed polygon whose test over its box comes down to its plane distance (<see cref="BspSphereQuery.EntryReachesPlane"/>).</summary>
    internal static bool IsPlaneItem(int item, out int entry)
    {
        entry = (item >> 2) - 1;
        return (item & 3) == TrueItem && item != TrueItem;
    }

    /// <summary>A guard item: the guard to ask (<see cref="Passes"/>); the next int is the length of the block to skip when it fails.</summary>
    internal static bool IsGuard(int item, out int guard)
    {
        guard = item >> 2;
        return (item & 3) == GuardTag;
    }

    /// <summary>
    /// A parent's frontier over a child's box: each node walked again as <see cref="Visit"/> walks it, each polygon
    /// tested again, each guard decided again (a block whose guard now always passes is inlined, one that never
    /// passes dropped). True when what is replayed blocks for every centre under the guards open around it.
    /// </summary>
    private bool Replay(ReadOnlySpan<int> program, int from, int to, in CentreBox box)
    {
        for (var i = from; i < to;)
        {
            var item = program[i++];
            if (IsNodeItem(item, out var node, out var centreCheck)) { if (Visit(node, centreCheck, box)) return true; }
            else if (IsPolygonItem(item, out var entry) || IsPlaneItem(item, out entry)) { if (Polygon(entry, box)) return true; }
            else if (IsGuard(item, out var guard))
            {
                var end = i + 1 + program[i];
                i++;
                switch (GuardOver(guard, box))
                {
                    case BoxDecision.True:
                        if (Replay(program, i, end, box)) return true;
                        break;
                    case BoxDecision.Mixed:
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

    private BoxDecision GuardOver(int guard, in CentreBox box)
    {
        var node = _nodes[guard >> 3];
        var kind = guard & 7;
        if (kind == SphereGuard) return SphereHits(node.SphereCenter, node.SphereRadius, box);
        if (kind >= BelowGuard)
        {
            var (min, max) = PlaneRange(node.Normal, node.D, box);
            var below = Not(Compare(min, max, 0.0, atLeast: true));
            return kind == BelowGuard ? below : Not(below);
        }
        var (atLeast, atMost) = Pushes(node, box);
        return kind == PushesPosGuard ? atLeast : atMost;
    }

    /// <summary>Whether the walk pushes the positive child (dist ≥ reach or not dist ≤ −reach) and the negative one (not dist ≥ reach), over the box.</summary>
    private (BoxDecision Pos, BoxDecision Neg) Pushes(in CompiledBspNode node, in CentreBox box)
    {
        var (min, max) = PlaneRange(node.Normal, node.D, box);
        var positive = Compare(min, max, _reach, atLeast: true);
        var negative = Compare(min, max, -_reach, atLeast: false);
        return (Or(positive, Not(negative)), Not(positive));
    }

    private static BoxDecision Not(BoxDecision t) => t switch { BoxDecision.True => BoxDecision.False, BoxDecision.False => BoxDecision.True, _ => BoxDecision.Mixed };

    private static BoxDecision Or(BoxDecision a, BoxDecision b) =>
        a == BoxDecision.True || b == BoxDecision.True ? BoxDecision.True : a == BoxDecision.False && b == BoxDecision.False ? BoxDecision.False : BoxDecision.Mixed;

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

    /// <summary>
    /// The walk of <see cref="BspSphereQuery.Overlaps"/> below one node over a box, the same decisions in the same
    /// order: true when it reaches a solid leaf with its centre check on for every centre under the guards open
    /// around it; what it cannot decide goes to <see cref="_scratch"/> as guards over blocks, polygons, or the
    /// node itself where its children's centre checks would depend on the centre's side of its plane.
    /// </summary>
    private bool Visit(int index, bool centreCheck, in CentreBox box)
    {
        var node = _nodes[index];
        var sphere = node.IsLeaf && node.ListedPolygonCount == 0 ? BoxDecision.False : SphereHits(node.SphereCenter, node.SphereRadius, box);
        if (node.IsLeaf)
        {
            if (node.ListedPolygonCount == 0) return false;
            if (centreCheck && node.Solid) return true;
            if (sphere == BoxDecision.False) return false;
            var leafGuard = sphere == BoxDecision.Mixed ? Open(index << 3 | SphereGuard) : -1;
            var touches = false;
            for (var k = 0; k < node.PolygonCount && !touches; k++)
                touches = Polygon(node.PolygonStart + k, box);
            if (leafGuard < 0) return touches;
            Close(leafGuard, touches);
            return false;
        }
        if (sphere == BoxDecision.False) return false;
        var (min, max) = PlaneRange(node.Normal, node.D, box);
        var positive = Compare(min, max, _reach, atLeast: true);
        var negative = Compare(min, max, -_reach, atLeast: false);
        var below = Compare(min, max, 0.0, atLeast: true) switch { BoxDecision.True => BoxDecision.False, BoxDecision.False => BoxDecision.True, _ => BoxDecision.Mixed };
        // Guards carry the pushes; the children's centre checks must come out the same wherever they are pushed,
        // which needs the centre's side settled when the middle band (both children) is reachable with the check on.
        var middle = positive != BoxDecision.True && negative != BoxDecision.True;
        var sided = centreCheck && middle && below == BoxDecision.Mixed;
        if ((_reach <= 0 && (positive == BoxDecision.Mixed || negative == BoxDecision.Mixed)) || (sided && !_splitSides))
        {
            _scratch.Add((index << 1 | (centreCheck ? 1 : 0)) << 2 | NodeTag);
            return false;
        }
        var pushPos = Or(positive, Not(negative));
        var pushNeg = Not(positive);
        var nodeGuard = sphere == BoxDecision.Mixed ? Open(index << 3 | SphereGuard) : -1;
        bool blocks;
        if (sided)
        {
            // The centre's side decides which child keeps the centre check (the negative one below the plane): one
            // block per side behind a side guard, the walk's own dist < 0 (a large subtree written out twice is left to
            // finer voxels, or to the tree's own index where its program grows long: SceneReachGrid).
            var under = Open(index << 3 | BelowGuard);
            Close(under, Branch(pushPos, node.Pos, false, index << 3 | PushesPosGuard, box) || Branch(pushNeg, node.Neg, true, index << 3 | PushesNegGuard, box));
            var over = Open(index << 3 | NotBelowGuard);
            Close(over, Branch(pushPos, node.Pos, true, index << 3 | PushesPosGuard, box) || Branch(pushNeg, node.Neg, false, index << 3 | PushesNegGuard, box));
            blocks = false;
        }
        else
        {
            var posCheck = centreCheck && (positive == BoxDecision.True || below == BoxDecision.False);
            var negCheck = centreCheck && (negative == BoxDecision.True || below == BoxDecision.True);
            blocks = Branch(pushPos, node.Pos, posCheck, index << 3 | PushesPosGuard, box)
                || Branch(pushNeg, node.Neg, negCheck, index << 3 | PushesNegGuard, box);
        }
        if (nodeGuard < 0) return blocks;
        Close(nodeGuard, blocks);
        return false;
    }

    /// <summary>One child as the walk pushes it: always, never, or behind its push guard.</summary>
    private bool Branch(BoxDecision pushed, int child, bool centreCheck, int guard, in CentreBox box)
    {
        if (pushed == BoxDecision.False || child < 0) return false;
        if (pushed == BoxDecision.True) return Visit(child, centreCheck, box);
        var mark = Open(guard);
        Close(mark, Visit(child, centreCheck, box));
        return false;
    }

    /// <summary>
    /// One listed polygon as LeafTouches tests it, over the box: dropped when its plane or bounding sphere rejects every
    /// centre; where the sphere is met and the contact point lies inside the polygon for every centre, only the plane
    /// distance decides (true: it touches at every centre; else a plane item); otherwise the polygon item.
    /// </summary>
    private bool Polygon(int entry, in CentreBox box)
    {
        var plane = _planes[entry];
        var (min, max) = PlaneRange(new Vector3(plane.X, plane.Y, plane.Z), plane.W, box);
        var nearest = min > 0 ? min : max < 0 ? -max : 0.0;
        if (nearest > _reach) return false;
        var sphere = _spheres[entry];
        var sum = (double)(sphere.W + _radius);
        var (lo, hi) = box.DistanceSquared(new Vector3(sphere.X, sphere.Y, sphere.Z));
        if (lo * (1 - SquareSlack) - Tiny > sum * sum * (1 + SquareSlack)) return false;
        if (hi * (1 + SquareSlack) + Tiny < sum * sum * (1 - SquareSlack) && ContactInside(_tree.LeafPolygon(entry), min, max, box))
        {
            if (Math.Max(Math.Abs(min), Math.Abs(max)) <= _reach) return true;
            _scratch.Add((entry + 1) << 2 | TrueItem);
            return false;
        }
        _scratch.Add(entry << 2 | PolygonTag);
        return false;
    }

    /// <summary>
    /// Whether PolygonSphereTest's interior test (the contact point c − n·dist on the inner side of every edge) passes
    /// for every centre of the box: each edge's side value is affine in the centre, its least value over the box
    /// bounded below past the rounding of dist, the contact point, the offset and the dot product.
    /// </summary>
    private static bool ContactInside(CompiledPolygon polygon, double distMin, double distMax, in CentreBox box)
    {
        var n = polygon.Normal;
        var maxDist = Math.Max(Math.Abs(distMin), Math.Abs(distMax));
        var reach = Math.Max(Math.Max(Math.Max(Math.Abs(box.LoX), Math.Abs(box.HiX)), Math.Max(Math.Abs(box.LoY), Math.Abs(box.HiY))), Math.Max(Math.Abs(box.LoZ), Math.Abs(box.HiZ)));
        foreach (var edge in polygon.Edges)
        {
            var w = edge.Inward;
            var start = edge.Start;
            var startReach = Math.Max(Math.Abs((double)start.X), Math.Max(Math.Abs((double)start.Y), Math.Abs((double)start.Z)));
            // side(c) = w · (c − start) − (w · n) · dist(c), dist(c) = n · c + d: affine in c with these coefficients.
            double wn = (double)w.X * n.X + (double)w.Y * n.Y + (double)w.Z * n.Z;
            double ax = w.X - wn * n.X, ay = w.Y - wn * n.Y, az = w.Z - wn * n.Z;
            var constant = -((double)w.X * start.X + (double)w.Y * start.Y + (double)w.Z * start.Z) - wn * polygon.D;
            var least = constant + (ax >= 0 ? ax * box.LoX : ax * box.HiX) + (ay >= 0 ? ay * box.LoY : ay * box.HiY) + (az >= 0 ? az * box.LoZ : az * box.HiZ);
            // Every float step's rounding is a few ulps of the largest magnitude it meets: the centre, the plane's d and
            // distance, the edge's start; all times the inward vector's size.
            var scale = (Math.Abs((double)w.X) + Math.Abs((double)w.Y) + Math.Abs((double)w.Z)) * (3 * reach + maxDist + Math.Abs((double)polygon.D) + 3 * startReach);
            if (!(scale < Huge) || !(least - 1e-5 * scale - Tiny >= 0)) return false;
        }
        return true;
    }

    /// <summary>NodeSphereHits over the box: |Δ|² &lt; (R + r)².</summary>
    private BoxDecision SphereHits(Vector3 center, float radius, in CentreBox box)
    {
        var sum = radius + _radius;
        var limit = (double)sum * sum;
        var (lo, hi) = box.DistanceSquared(center);
        if (!(hi < Huge)) return BoxDecision.Mixed;
        if (hi * (1 + SquareSlack) + Tiny < limit * (1 - SquareSlack)) return BoxDecision.True;
        if (lo * (1 - SquareSlack) - Tiny >= limit * (1 + SquareSlack)) return BoxDecision.False;
        return BoxDecision.Mixed;
    }

    /// <summary>BroadPhaseHits over the box: |Δ|² − (R + r)² &lt; ε, the subtraction's rounding bounded too.</summary>
    private BoxDecision BroadPhase(in CompiledBspNode root, in CentreBox box)
    {
        var sum = root.SphereRadius + _radius;
        if (float.IsPositiveInfinity(sum * sum)) return BoxDecision.True;
        var limit = (double)sum * sum;
        var (lo, hi) = box.DistanceSquared(root.SphereCenter);
        if (!(hi < Huge)) return BoxDecision.Mixed;
        var upper = hi * (1 + SquareSlack) + Tiny - limit * (1 - SquareSlack);
        if (upper + Math.Abs(upper) * 1e-6 + Tiny < PhysicsEpsilon.Value) return BoxDecision.True;
        var lower = lo * (1 - SquareSlack) - Tiny - limit * (1 + SquareSlack);
        if (lower - Math.Abs(lower) * 1e-6 - Tiny >= PhysicsEpsilon.Value) return BoxDecision.False;
        return BoxDecision.Mixed;
    }

    /// <summary>dist ≥ value (atLeast) or dist ≤ value over the range of dist.</summary>
    private static BoxDecision Compare(double min, double max, double value, bool atLeast)
    {
        if (atLeast) return min >= value ? BoxDecision.True : max < value ? BoxDecision.False : BoxDecision.Mixed;
        return max <= value ? BoxDecision.True : min > value ? BoxDecision.False : BoxDecision.Mixed;
    }

    /// <summary>
    /// The range of dot(n, c) + d over the box, widened by a bound on the float evaluation's rounding (a few ulps
    /// of the largest term); unbounded when a term could overflow a float.
    /// </summary>
    private static (double Min, double Max) PlaneRange(Vector3 n, float d, in CentreBox box)
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
}
