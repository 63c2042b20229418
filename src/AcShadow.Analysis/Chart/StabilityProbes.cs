using System.Collections.Immutable;
using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Probes placed where methods fail. For every polygon surface — each BSP part of the reference and each
/// solid a model fitted to a part (its boxes' and hulls' faces: where a model's answer flips is where it
/// can differ from the reference's) — and every mover radius r, in the part's own space (where retail
/// applies ε: radius r/scale), spheres whose contact distance r − ε falls
/// <see cref="ChartOptions.StabilityOffset"/> short of and past
/// <list type="bullet">
/// <item>points all over each face (its centroid and a lattice every <see cref="ChartOptions.Spacing"/>),
/// from the front and from behind, and centres that far either side of the face itself (6 per point);</item>
/// <item>points along each edge at the same spacing, along the bisector of the faces that share it (2 per point);</item>
/// <item>each vertex, along the mean normal of its faces (2 per vertex);</item>
/// <item>each BSP splitting plane at the foot of its node's sphere centre, both sides, and across the plane itself (6 per node).</item>
/// </list>
/// The offset and spacing are metres in entity space. A model that agrees with the reference on these
/// agrees where a grid is too coarse to look: at the boundary.
/// </summary>
internal static class StabilityProbes
{
    /// <summary>Face lattice points at most, per polygon (a huge polygon is sampled more coarsely).</summary>
    public const int MaxPointsPerPolygon = 2000;

    /// <summary>What <see cref="Laid"/> built: the probes, and how many times the spacing was multiplied to stay under the limit (1: not at all).</summary>
    public sealed record Laid(IReadOnlyList<Probe> Probes, float SpacingFactor);

    public static IReadOnlyList<Probe> Build(IEnumerable<PreparedShape> surfaces, ChartOptions options) => Lay(surfaces, options).Probes;

    /// <summary>The probes for every surface, the spacing coarsened (doubled) as often as <see cref="ChartOptions.MaxStabilityProbes"/> needs.</summary>
    public static Laid Lay(IEnumerable<PreparedShape> surfaces, ChartOptions options)
    {
        var all = surfaces.ToArray();
        var factor = 1f;
        // Counted before anything is built; the points on faces and edges fall as the spacing grows, those at
        // centroids, vertices and nodes do not (and are bounded by the bytes the dat spent on them).
        while (factor < 1e30f && all.Sum(s => Count(s, options, factor)) > options.MaxStabilityProbes) factor *= 2f;
        var probes = new List<Probe>();
        foreach (var shape in all)
        {
            if (shape.Polytope is { } solid) Add(probes, shape.Pose, [.. solid.Faces], [], options, factor);
            else if (shape.Bsp is { } bsp) Add(probes, shape.Pose, bsp.Polygons, bsp.Nodes, options, factor);
        }
        return new Laid(probes, factor);
    }

    /// <summary>How many probes <see cref="Add"/> would place for one surface with the spacing multiplied by <paramref name="factor"/>.</summary>
    private static long Count(PreparedShape shape, ChartOptions options, float factor)
    {
        ImmutableArray<CompiledPolygon> polygons = [];
        ImmutableArray<CompiledBspNode> nodes = [];
        if (shape.Polytope is { } solid) polygons = [.. solid.Faces];
        else if (shape.Bsp is { } bsp) (polygons, nodes) = (bsp.Polygons, bsp.Nodes);
        var step = options.Spacing * factor / shape.Pose.Scale;
        long face = 0, edge = 0, vertex = 0, plane = 0;
        foreach (var polygon in polygons)
        {
            var v = polygon.Vertices;
            face += 1 + LatticeCount(v, step);
            vertex += v.Length; // an upper bound: shared vertices are probed once
            for (var i = 0; i < v.Length; i++)
                edge += EdgePoints(v[i == 0 ? v.Length - 1 : i - 1], v[i], step); // shared edges counted twice: an upper bound
        }
        foreach (var node in nodes)
            if (!node.IsLeaf && node.Normal != Vector3.Zero && float.IsFinite(node.SphereRadius)) plane++;
        return options.Radii.Count * (6 * face + 2 * edge + 2 * vertex + 6 * plane);
    }

    /// <summary>The same probes for one tree posed in entity space (an indoor cell's structure in its cell's frame).</summary>
    public static IReadOnlyList<Probe> Build(CompiledBsp bsp, PartPose pose, ChartOptions options)
    {
        var probes = new List<Probe>();
        Add(probes, pose, bsp.Polygons, bsp.Nodes, options, 1f);
        return probes;
    }

    private static void Add(List<Probe> probes, PartPose pose, ImmutableArray<CompiledPolygon> polygons, ImmutableArray<CompiledBspNode> nodes, ChartOptions options, float factor)
    {
        var delta = options.StabilityOffset / pose.Scale;
        var step = options.Spacing * factor / pose.Scale;
        var edges = new Dictionary<(Vector3, Vector3), (Vector3 A, Vector3 B, Vector3 Normals, Vector3 Out, int Count)>();
        var vertices = new Dictionary<Vector3, Vector3>();
        var facePoints = new List<(Vector3 At, Vector3 Normal)>();
        foreach (var polygon in polygons)
        {
            var v = polygon.Vertices;
            var n = polygon.Normal;
            facePoints.Add((Centroid(v), n));
            foreach (var p in Lattice(v, step)) facePoints.Add((p, n));
            for (var i = 0; i < v.Length; i++)
            {
                var a = v[i == 0 ? v.Length - 1 : i - 1];
                var b = v[i];
                var key = Less(a, b) ? (a, b) : (b, a);
                edges[key] = edges.TryGetValue(key, out var e)
                    ? (e.A, e.B, e.Normals + n, e.Out, e.Count + 1)
                    : (a, b, n, Unit(-Cross(n, b - a), n), 1);
                vertices[b] = vertices.GetValueOrDefault(b) + n;
            }
        }
        foreach (var radius in options.Radii)
        {
            var reach = radius / pose.Scale - PhysicsEpsilon.Value;
            void Place(Vector3 local, ProbeKind kind) => probes.Add(new Probe(pose.ToEntity(local), radius, kind));
            void Across(Vector3 foot, Vector3 n, ProbeKind kind)
            {
                foreach (var side in (ReadOnlySpan<float>)[1f, -1f])
                    foreach (var t in (ReadOnlySpan<float>)[-1f, 1f]) Place(foot + n * (side * reach + t * delta), kind);
                foreach (var t in (ReadOnlySpan<float>)[-1f, 1f]) Place(foot + n * (t * delta), kind);
            }
            foreach (var (at, n) in facePoints) Across(at, n, ProbeKind.Face);
            foreach (var e in edges.Values)
            {
                var dir = e.Count == 1 ? Unit(e.Normals + e.Out, e.Normals) : Unit(e.Normals, e.Out);
                var count = EdgePoints(e.A, e.B, step);
                for (var m = 0; m < count; m++)
                {
                    var mid = e.A + (e.B - e.A) * ((m + 0.5f) / count);
                    foreach (var t in (ReadOnlySpan<float>)[-1f, 1f]) Place(mid + dir * (reach + t * delta), ProbeKind.Edge);
                }
            }
            foreach (var (at, normals) in vertices)
            {
                var dir = Unit(normals, Vector3.UnitZ);
                foreach (var t in (ReadOnlySpan<float>)[-1f, 1f]) Place(at + dir * (reach + t * delta), ProbeKind.Vertex);
            }
            foreach (var node in nodes)
            {
                if (node.IsLeaf || node.Normal == Vector3.Zero || !float.IsFinite(node.SphereRadius)) continue;
                var c = node.SphereCenter;
                var dist = node.Normal.X * c.X + node.Normal.Y * c.Y + node.Normal.Z * c.Z + node.D;
                Across(c - node.Normal * dist, node.Normal, ProbeKind.SplittingPlane);
            }
        }
    }

    private static int EdgePoints(Vector3 a, Vector3 b, float step) =>
        Math.Clamp((int)MathF.Ceiling(MathF.Sqrt(Vector3DistanceSquared(a, b)) / step), 1, MaxPointsPerPolygon);

    /// <summary>The lattice divisions of one fan triangle (points are laid only when it is 2 or more).</summary>
    private static int Divisions(Vector3 a, Vector3 b, Vector3 c, float step)
    {
        var longest = MathF.Sqrt(MathF.Max(Vector3DistanceSquared(a, b), MathF.Max(Vector3DistanceSquared(b, c), Vector3DistanceSquared(a, c))));
        // Capped, and squared in long: a damaged part's edge can be 1e38 m or +∞ long, and
        // an int k squared there overflowed, passed the limit and laid points without end.
        var wanted = MathF.Ceiling(longest / step);
        if (float.IsNaN(wanted)) return 0;
        var k = (long)MathF.Min(wanted, 1 << 20);
        while (k > 1 && (k + 1) * (k + 2) / 2 > MaxPointsPerPolygon) k /= 2;
        return (int)k;
    }

    /// <summary>How many points <see cref="Lattice"/> yields, without yielding them.</summary>
    private static long LatticeCount(ImmutableArray<Vector3> v, float step)
    {
        long count = 0;
        for (var t = 1; t + 1 < v.Length; t++)
        {
            var k = Divisions(v[0], v[t], v[t + 1], step);
            // All (i, j) with i + j ≤ k but the three corners, as Lattice lays them.
            if (k >= 2) count += (long)(k + 1) * (k + 2) / 2 - 3;
        }
        return count;
    }

    /// <summary>
    /// Points over a polygon's fan triangles on a barycentric lattice about <paramref name="step"/> apart,
    /// corners left out (the vertex probes cover them); none for a polygon smaller than the step.
    /// </summary>
    private static IEnumerable<Vector3> Lattice(ImmutableArray<Vector3> v, float step)
    {
        for (var t = 1; t + 1 < v.Length; t++)
        {
            Vector3 a = v[0], b = v[t], c = v[t + 1];
            var k = Divisions(a, b, c, step);
            if (k < 2) continue;
            for (var i = 0; i <= k; i++)
                for (var j = 0; i + j <= k; j++)
                {
                    if ((i == 0 && j == 0) || i == k || j == k) continue;
                    yield return a + (b - a) * ((float)i / k) + (c - a) * ((float)j / k);
                }
        }
    }

    private static float Vector3DistanceSquared(Vector3 a, Vector3 b)
    {
        float dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
        return dx * dx + dy * dy + dz * dz;
    }

    private static Vector3 Centroid(ImmutableArray<Vector3> v)
    {
        var sum = Vector3.Zero;
        foreach (var p in v) sum += p;
        return sum / v.Length;
    }

    private static bool Less(Vector3 a, Vector3 b) => a.X != b.X ? a.X < b.X : a.Y != b.Y ? a.Y < b.Y : a.Z < b.Z;

    private static Vector3 Cross(Vector3 a, Vector3 b) => new(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

    /// <summary>v made unit length in scalar arithmetic (the same bits on every machine); <paramref name="fallback"/> when v is (nearly) zero.</summary>
    private static Vector3 Unit(Vector3 v, Vector3 fallback)
    {
        var length = MathF.Sqrt(v.X * v.X + v.Y * v.Y + v.Z * v.Z);
        if (!(length > 1e-6f)) return fallback;
        return new Vector3(v.X / length, v.Y / length, v.Z / length);
    }
}
