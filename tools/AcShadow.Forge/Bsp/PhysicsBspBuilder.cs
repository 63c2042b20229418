using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Geometry;

namespace AcShadow.Forge.Bsp;

/// <summary>
/// Builds a GfxObj's PhysicsBSP from its physics polygons. Pure and deterministic.
/// <list type="bullet">
/// <item>Splitting planes are polygons' own retail planes (<see cref="PolygonPlane.Compute"/>), so every
/// internal plane equals some polygon's plane bit for bit; degenerate polygons are never splitters.</item>
/// <item>Polygons are never cut (leaves must name the GfxObj's own polygon ids): a polygon with vertices on
/// both sides goes to both children; one lying in the plane goes to the side its normal faces.</item>
/// <item>Choice: lowest score = 4 × spanning + |pos − neg|, ties to the lowest polygon id. Pure
/// "fewest spanning first" turns every convex piece into a one-polygon-per-level chain.</item>
/// <item>Open meshes stop at ≤ <see cref="MaxLeafPolygons"/> polygons or when no plane separates the set.
/// Closed meshes (every edge used once in each direction: a watertight, consistently wound solid) are
/// split until every plane on the way has been used, including a last split by a plane with nothing
/// behind it, so that the inside of the solid ends up in empty negative leaves. Every mesh stops at
/// <see cref="MaxDepth"/> (the reader refuses trees deeper than 256).</item>
/// <item>Solid rule: a leaf is solid (Solid = 1) exactly when it holds no polygons, is the negative child
/// of its parent, and the mesh is closed: behind an outward-facing surface of a closed mesh, with no
/// surface further in, is the inside. Leaves holding polygons are never solid; open meshes get no empty
/// leaves (the child is absent and the tag says so).</item>
/// <item>Every node's sphere contains every vertex of every polygon below it; an empty leaf takes its
/// parent's sphere. The root's sphere is the part's broad-phase sphere.</item>
/// </list>
/// </summary>
public static class PhysicsBspBuilder
{
    /// <summary>A vertex this close to a plane (metres) counts as on it.</summary>
    public const float OnPlaneEpsilon = 1e-4f;
    public const int MaxLeafPolygons = 4;
    public const int MaxDepth = 64;
    /// <summary>Planes tried per node; large sets sample evenly so 300-polygon parts stay fast.</summary>
    public const int MaxCandidates = 48;

    private enum Side { Pos, Neg, Both }

    private sealed record Poly(int Id, Vector3[] Points, Plane? Plane);

    /// <summary>Polygon i of <paramref name="polygons"/> (vertex ids into <paramref name="vertices"/>) gets id i.</summary>
    public static PhysicsBspNode Build(IReadOnlyList<Vector3> vertices, IReadOnlyList<IReadOnlyList<short>> polygons)
    {
        if (polygons.Count == 0) throw new ArgumentException("a PhysicsBSP needs at least one polygon", nameof(polygons));
        var polys = new Poly[polygons.Count];
        for (var i = 0; i < polys.Length; i++)
        {
            var points = polygons[i].Select(v => vertices[v]).ToArray();
            polys[i] = new Poly(i, points, PolygonPlane.Compute(points));
        }
        var state = new BuildState(polys, IsClosed(polygons));
        return state.Node(Enumerable.Range(0, polys.Length).ToArray(), 0, null);
    }

    private sealed class BuildState(Poly[] polys, bool closed)
    {
        private int _nextLeaf;
        private readonly List<Plane> _path = [];

        public PhysicsBspNode Node(int[] set, int depth, Sphere? parentSphere)
        {
            var sphere = set.Length == 0 ? parentSphere!.Value : Bounds(set);
            if (!closed && set.Length <= MaxLeafPolygons || depth >= MaxDepth || ChooseSplitter(set) is not { } splitter)
                return Leaf(set, sphere, solid: false);

            var pos = new List<int>(set.Length);
            var neg = new List<int>(set.Length);
            foreach (var i in set)
            {
                var side = Classify(polys[i], splitter);
                if (side != Side.Neg) pos.Add(i);
                if (side != Side.Pos) neg.Add(i);
            }
            _path.Add(splitter);
            var posChild = pos.Count > 0 ? Node([.. pos], depth + 1, sphere) : null;
            var negChild = neg.Count > 0 ? Node([.. neg], depth + 1, sphere)
                : closed ? Leaf([], sphere, solid: true) : null;
            _path.RemoveAt(_path.Count - 1);
            return new PhysicsBspNode(BspNodeTypes.ForChildren(posChild is not null, negChild is not null),
                splitter, posChild, negChild, sphere, 0, 0, []);
        }

        private PhysicsBspNode Leaf(int[] set, Sphere sphere, bool solid) =>
            new(BspNodeType.Leaf, default, null, null, sphere, _nextLeaf++, solid ? 1 : 0, set.Select(i => (ushort)polys[i].Id).ToArray());

        private Plane? ChooseSplitter(int[] set)
        {
            var candidates = new List<Plane>();
            foreach (var i in set)
                if (polys[i].Plane is { } plane && !candidates.Contains(plane) && !_path.Contains(plane)) candidates.Add(plane);
            if (candidates.Count > MaxCandidates)
                candidates = Enumerable.Range(0, MaxCandidates).Select(k => candidates[k * candidates.Count / MaxCandidates]).ToList();

            Plane? best = null;
            var bestScore = int.MaxValue;
            foreach (var plane in candidates)
            {
                int pos = 0, neg = 0, spanning = 0;
                foreach (var i in set)
                {
                    switch (Classify(polys[i], plane))
                    {
                        case Side.Pos: pos++; break;
                        case Side.Neg: neg++; break;
                        default: pos++; neg++; spanning++; break;
                    }
                }
                // A split must separate something; in a closed mesh a plane with nothing behind it also
                // counts (it walls off the inside: the empty negative side becomes a solid leaf).
                if (neg == set.Length || pos == set.Length && !(closed && neg == 0)) continue;
                var score = 4 * spanning + Math.Abs(pos - neg);
                if (score < bestScore) { bestScore = score; best = plane; }
            }
            return best;
        }

        private static Side Classify(Poly poly, Plane plane)
        {
            float min = float.MaxValue, max = float.MinValue;
            foreach (var p in poly.Points)
            {
                var d = PolygonPlane.Distance(plane, p);
                min = MathF.Min(min, d);
                max = MathF.Max(max, d);
            }
            if (min >= -OnPlaneEpsilon && max <= OnPlaneEpsilon)
                return poly.Plane is { } own && PolygonPlane.Dot(own.Normal, plane.Normal) < 0f ? Side.Neg : Side.Pos;
            if (min >= -OnPlaneEpsilon) return Side.Pos;
            if (max <= OnPlaneEpsilon) return Side.Neg;
            return Side.Both;
        }

        /// <summary>Box centre, farthest vertex, widened by a hair so float rounding never leaves a vertex outside.</summary>
        private Sphere Bounds(int[] set)
        {
            var min = new Vector3(float.MaxValue);
            var max = new Vector3(float.MinValue);
            foreach (var i in set)
                foreach (var p in polys[i].Points) { min = Vector3.Min(min, p); max = Vector3.Max(max, p); }
            var center = (min + max) * 0.5f;
            double farthest = 0;
            foreach (var i in set)
                foreach (var p in polys[i].Points)
                {
                    double dx = p.X - center.X, dy = p.Y - center.Y, dz = p.Z - center.Z;
                    farthest = Math.Max(farthest, dx * dx + dy * dy + dz * dz);
                }
            var radius = Math.Sqrt(farthest);
            return new Sphere(center, (float)(radius * (1 + 1e-6) + 1e-6));
        }
    }

    /// <summary>Closed: every directed edge a→b is matched by exactly one b→a (consistently wound, watertight).</summary>
    public static bool IsClosed(IReadOnlyList<IReadOnlyList<short>> polygons)
    {
        var edges = new Dictionary<(short, short), int>();
        foreach (var poly in polygons)
            for (var k = 0; k < poly.Count; k++)
            {
                var edge = (poly[k], poly[(k + 1) % poly.Count]);
                if (edge.Item1 == edge.Item2) return false;
                edges[edge] = edges.GetValueOrDefault(edge) + 1;
            }
        foreach (var ((a, b), count) in edges)
            if (count != 1 || edges.GetValueOrDefault((b, a)) != 1) return false;
        return true;
    }
}
