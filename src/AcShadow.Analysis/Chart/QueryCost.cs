using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// What answering one query costs a model, counted, not timed: the same count on every machine and run,
/// so a choice made by it is reproducible where a choice by wall time is not. The unit is one distance
/// evaluation (a plane distance, dot + d, or a squared distance against a sphere: about 6 float
/// operations). Weights from the float operations of each step:
/// <list type="bullet">
/// <item>moving the sphere into a part's, object's or cell's frame (<see cref="PartPose.ToLocal"/>, a
/// quaternion turn of about 30 float operations): <see cref="Transform"/>;</item>
/// <item>a Sphere: 1; a Cylinder: 2 (the disc, then the height);</item>
/// <item>a part box (<see cref="BoxSphereQuery"/>): the turn, then 2 (the three slab excesses and the corner distance);</item>
/// <item>a part hull (<see cref="ConvexPolytope"/>): the turn, its bounding sphere 1, each face plane it
/// evaluates 1, and each face it then touch-tests 1 + its edges;</item>
/// <item>a BSP part (<see cref="BspSphereQuery"/>): the turn, the root broad phase 1, each node visited 2
/// (its sphere and its plane), each leaf sphere 1, each leaf polygon's plane 1 and, for a polygon the
/// sphere reaches, its bounding sphere 1 and the edge walk 1 + its edges;</item>
/// <item>a BSP part asked through its voxel index (<see cref="BspReachGrid"/>, the compiled scene): the turn, the
/// voxel lookup 1, the root broad phase 1 where the voxel leaves it open, then each frontier item as the walk
/// counts it (a node's walk from there; a polygon's plane 1 and, reached, 2 + its edges; a guard's sphere or plane 1).</item>
/// </list>
/// An object's shapes are asked in order and the count stops at the first that blocks, as the query does.
/// Counted over an evenly strided sample of the probes (the one the timer takes), averaged per query.
/// </summary>
internal static class QueryCost
{
    public const int Transform = 5;

    /// <summary>Average count per query over at most <paramref name="sample"/> evenly strided probes (0 for none).</summary>
    public static double PerQuery(IReadOnlyList<PreparedShape> shapes, IReadOnlyList<Probe> probes, int sample)
    {
        if (probes.Count == 0 || sample < 1) return 0;
        var counter = new Counter(shapes);
        var n = Math.Min(sample, probes.Count);
        long total = 0;
        for (var i = 0; i < n; i++)
        {
            var p = probes[(int)((long)i * probes.Count / n)];
            total += counter.Count(p.Center, p.Radius, out _);
        }
        return (double)total / n;
    }

    /// <summary>
    /// A model's shapes made ready to be counted, query after query. With <paramref name="partReach"/> a posed part
    /// (tree, box, hull) first costs 1 for its reach in the entity frame (<see cref="PartReach"/>, which
    /// <see cref="PosedQuery"/> tests), and a sphere beyond it costs nothing more. The scene counts so; a model's own
    /// count (<see cref="PerQuery"/>, which orders the ladder) is left as the ladder was tuned. With
    /// <paramref name="grids"/>, its trees are counted as asked through their voxel indexes.
    /// </summary>
    public sealed class Counter(IReadOnlyList<PreparedShape> shapes, bool partReach = false, BspReachGrids? grids = null)
    {
        private readonly Shape[] _shapes = [.. shapes.Select(s => Shape.Of(s, partReach, grids))];

        /// <summary>The count for one query, and whether the model blocks there.</summary>
        public int Count(Vector3 center, float radius, out bool blocked)
        {
            blocked = false;
            if (!Finite(center) || !float.IsFinite(radius) || radius < 0f) return 0;
            var ops = 0;
            foreach (var shape in _shapes)
            {
                ops += shape.Count(center, radius, out blocked);
                if (blocked) return ops;
            }
            return ops;
        }
    }

    private abstract class Shape
    {
        public abstract int Count(Vector3 center, float radius, out bool blocked);

        public static Shape Of(PreparedShape s, bool partReach, BspReachGrids? grids) => s switch
        {
            { Box: { } box } => Reached(s.Pose, LocalBound.OfBox(box), new BoxShape(s.Pose, new BoxSphereQuery(box)), partReach),
            { Polytope: { } hull } => Reached(s.Pose, hull.Bound, new HullShape(s.Pose, hull), partReach),
            { Bsp: { } bsp } => Reached(s.Pose, LocalBound.OfTree(bsp), new BspShape(s.Pose, bsp, grids), partReach),
            _ when s.Shape.CollisionType == CollisionType.Cylinder => new CylinderShape(s.Shape),
            _ => new SphereShape(s.Shape),
        };

        private static Shape Reached(PartPose pose, (Vector3 Center, float Radius)? local, Shape shape, bool partReach) =>
            partReach && PartReach.Of(pose, local) is { IsBounded: true } reach ? new ReachedShape(reach, shape) : shape;
    }

    /// <summary>A posed part behind its reach in the entity frame: 1, then the part's own count when the sphere is within it.</summary>
    private sealed class ReachedShape(PartReach reach, Shape part) : Shape
    {
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            blocked = false;
            if (!reach.Reaches(center, radius)) return 1;
            return 1 + part.Count(center, radius, out blocked);
        }
    }

    private sealed class SphereShape(ShadowShape s) : Shape
    {
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            blocked = SphereSphereTest.Touches(s.LocalPosition, s.Radius, center, radius);
            return 1;
        }
    }

    private sealed class CylinderShape(ShadowShape s) : Shape
    {
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            blocked = CylinderSphereTest.Touches(s.LocalPosition, s.Radius, s.CylHeight, center, radius);
            return 2;
        }
    }

    private sealed class BoxShape(PartPose pose, BoxSphereQuery box) : Shape
    {
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            var (local, r) = pose.ToLocal(center, radius);
            blocked = box.Overlaps(local, r);
            return Transform + 2;
        }
    }

    private sealed class HullShape : Shape
    {
        private readonly PartPose _pose;
        private readonly ConvexPolytope _hull;
        private readonly IReadOnlyList<CompiledPolygon> _faces;
        private readonly Vector3 _boundCenter;
        private readonly float _boundRadius;

        public HullShape(PartPose pose, ConvexPolytope hull)
        {
            _pose = pose;
            _hull = hull;
            _faces = hull.Faces;
            (_boundCenter, _boundRadius) = BoundOf(hull.Vertices);
        }

        /// <summary>The walk <see cref="ConvexPolytope.Overlaps"/> takes, counted; its answer is the polytope's own.</summary>
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            var (local, r) = _pose.ToLocal(center, radius);
            blocked = _hull.Overlaps(local, r);
            var ops = Transform + 1;
            if (_faces.Count == 0 || DistanceSquared(local, _boundCenter) > (_boundRadius + r) * (_boundRadius + r)) return ops;
            var reach = r - PhysicsEpsilon.Value;
            var deepest = float.NegativeInfinity;
            foreach (var face in _faces)
            {
                ops++;
                var dist = face.Distance(local);
                if (dist >= reach) return ops;
                deepest = MathF.Max(deepest, dist);
            }
            if (deepest < 0f) return ops;
            foreach (var face in _faces)
            {
                ops++;
                if (face.Distance(local) < 0f) continue;
                ops += 1 + face.Vertices.Length;
                if (PolygonSphereTest.Touches(face, local, r)) return ops;
            }
            return ops;
        }
    }

    /// <summary>
    /// A settled frontier (<see cref="BspBoxWalk"/>: a voxel of a tree's or a scene's grid) at a part-local centre,
    /// counted item by item as the walk counts what it runs: the root's broad phase 1 when guarded, each guard 1, each
    /// polygon as the walk counts it, each plane item 1, each node's walk.
    /// </summary>
    public static int Frontier(CompiledBsp bsp, ReadOnlySpan<int> items, bool guarded, Vector3 local, float r, out bool blocked)
    {
        blocked = false;
        var nodes = bsp.Nodes;
        var reach = r - PhysicsEpsilon.Value;
        var ops = 0;
        if (guarded)
        {
            ops++;
            var root = nodes[0];
            if (DistanceSquared(root.SphereCenter, local) - (root.SphereRadius + r) * (root.SphereRadius + r) >= PhysicsEpsilon.Value) return ops;
            if (items.IsEmpty) { blocked = true; return ops; }
        }
        for (var i = 0; i < items.Length;)
        {
            var item = items[i++];
            if (BspBoxWalk.IsNodeItem(item, out var node, out var centreCheck)) ops += Walk(bsp, node << 1 | (centreCheck ? 1 : 0), local, r, reach, out blocked);
            else if (BspBoxWalk.IsPolygonItem(item, out var entry)) ops += PolygonCount(bsp.Polygons[bsp.LeafPolygons[entry]], local, r, reach, out blocked);
            else if (BspBoxWalk.IsPlaneItem(item, out entry))
            {
                ops++;
                blocked = !(MathF.Abs(bsp.Polygons[bsp.LeafPolygons[entry]].Distance(local)) > reach);
            }
            else if (BspBoxWalk.IsGuard(item, out var guard))
            {
                ops++;
                var length = items[i++];
                if (!BspBoxWalk.Passes(nodes.AsSpan(), guard, local, r, reach)) i += length;
            }
            else blocked = true;
            if (blocked) return ops;
        }
        return ops;
    }

    private sealed class BspShape(PartPose pose, CompiledBsp bsp, BspReachGrids? grids) : Shape
    {
        /// <summary>The walk <see cref="BspSphereQuery.Overlaps"/> takes (same pruning, same order), counted; or the voxel index's path to the same answer.</summary>
        public override int Count(Vector3 center, float radius, out bool blocked)
        {
            blocked = false;
            var (local, r) = pose.ToLocal(center, radius);
            var nodes = bsp.Nodes;
            var ops = Transform + 1;
            if (nodes.Length == 0 || !Finite(local)) return ops;
            var root = nodes[0];
            var reach = r - PhysicsEpsilon.Value;
            if (grids?.Find(bsp, r) is { } grid && grid.Code(local) is var code && !BspReachGrid.IsOutside(code))
            {
                blocked = BspReachGrid.IsBlocked(code);
                if (BspReachGrid.IsClear(code) || blocked) return ops;
                var items = grid.Frontier(code, out var guarded);
                return ops + Frontier(bsp, items, guarded, local, r, out blocked);
            }
            if (DistanceSquared(root.SphereCenter, local) - (root.SphereRadius + r) * (root.SphereRadius + r) >= PhysicsEpsilon.Value) return ops;
            return ops + Walk(bsp, 1, local, r, reach, out blocked);
        }
    }

    /// <summary>The walk below one entry (node &lt;&lt; 1 | centre check), counted.</summary>
    private static int Walk(CompiledBsp bsp, int start, Vector3 local, float r, float reach, out bool blocked)
    {
        blocked = false;
        var nodes = bsp.Nodes;
        var ops = 0;
        var top = 0;
        Span<int> stack = nodes.Length <= 512 ? stackalloc int[nodes.Length * 2 + 2] : new int[nodes.Length * 2 + 2];
        stack[top++] = start;
        while (top > 0)
        {
            var entry = stack[--top];
            var node = nodes[entry >> 1];
            var centreCheck = (entry & 1) != 0;
            if (node.IsLeaf)
            {
                if (node.ListedPolygonCount == 0) continue;
                if (centreCheck && node.Solid) { blocked = true; return ops; }
                ops++;
                if (!(DistanceSquared(node.SphereCenter, local) < (node.SphereRadius + r) * (node.SphereRadius + r))) continue;
                for (var k = 0; k < node.PolygonCount; k++)
                {
                    ops += PolygonCount(bsp.Polygons[bsp.LeafPolygons[node.PolygonStart + k]], local, r, reach, out blocked);
                    if (blocked) return ops;
                }
                continue;
            }
            ops += 2;
            if (!(DistanceSquared(node.SphereCenter, local) < (node.SphereRadius + r) * (node.SphereRadius + r))) continue;
            var dist = PolygonPlane.Dot(node.Normal, local) + node.D;
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
        return ops;
    }

    private static int PolygonCount(CompiledPolygon polygon, Vector3 local, float r, float reach, out bool blocked)
    {
        blocked = false;
        if (MathF.Abs(polygon.Distance(local)) > reach) return 1;
        blocked = PolygonSphereTest.Touches(polygon, local, r);
        return 3 + polygon.Vertices.Length;
    }

    private static void Push(Span<int> stack, ref int top, int child, bool centreCheck)
    {
        if (child >= 0) stack[top++] = child << 1 | (centreCheck ? 1 : 0);
    }

    private static (Vector3 Center, float Radius) BoundOf(IReadOnlyList<Vector3> vertices)
    {
        if (vertices.Count == 0) return (Vector3.Zero, 0f);
        var min = new Vector3(float.PositiveInfinity);
        var max = new Vector3(float.NegativeInfinity);
        foreach (var v in vertices) { min = Vector3.Min(min, v); max = Vector3.Max(max, v); }
        var center = new Vector3((min.X + max.X) * 0.5f, (min.Y + max.Y) * 0.5f, (min.Z + max.Z) * 0.5f);
        var far = 0f;
        foreach (var v in vertices) far = MathF.Max(far, DistanceSquared(v, center));
        return (center, MathF.Sqrt(far) * 1.0001f + 1e-5f);
    }

    private static float DistanceSquared(Vector3 a, Vector3 b)
    {
        float dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
        return dx * dx + dy * dy + dz * dz;
    }

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
