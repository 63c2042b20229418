using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Forging.Bsp;

/// <summary>
/// Builds a GfxObj's PhysicsBSP from its physics polygons, in the retail convention: the solid cells are
/// leaves that HOLD polygons (BSPLEAF::sphere_intersects_solid returns "clear" on NumPolys == 0 before its
/// centre check; ACE's BSPLEAF::point_intersects_solid is NumPolys != 0). Pure and deterministic.
/// <list type="bullet">
/// <item>Splitting planes are polygons' own retail planes (<see cref="PolygonPlane.Compute"/>), so every
/// internal plane equals some polygon's plane bit for bit; degenerate polygons are never splitters.</item>
/// <item>Polygons are never cut (leaves must name the GfxObj's own polygon ids): a polygon with vertices on
/// both sides goes to both children. A polygon lying in the plane goes to the side BEHIND it, the side of
/// the solid it bounds: negative when it faces the way the plane does (always so for the splitter's own
/// polygon), positive when it faces the other way (the back of a wall built as two opposite faces, or a
/// box standing on a floor: the box's bottom bounds the box above the floor, the floor the ground below).
/// A degenerate polygon lying in the plane goes to the negative side.</item>
/// <item>Choice: lowest score = 4 × spanning + |pos − neg|, ties to the lowest polygon id.</item>
/// <item>Open meshes stop at ≤ <see cref="MaxLeafPolygons"/> polygons or when no plane separates the set,
/// and have no solid leaves: an open surface has no inside.</item>
/// <item>Closed meshes (every edge used once in each direction: watertight, consistently wound) are split
/// by the planes of polygons that still cross the inside of the leaf's cell (the cell: the path's
/// half-spaces, shrunk by <see cref="OnPlaneEpsilon"/>) until none does, so every leaf cell lies wholly
/// inside or wholly outside the mesh. Solid rule: a leaf is solid (Solid = 1) exactly when it holds
/// polygons and its cell is inside the mesh, decided by the winding number (sum of solid angles) of the
/// whole mesh at a point inside the cell, built from the leaf's polygons that lie on the cell's boundary
/// (each offset a little into the cell; the deepest such point is used). An empty side is normally
/// empty space; when the side in front of a splitter holds no polygons but is still inside the
/// mesh (one closed piece pushed into another, e.g. a leg into a slab), its leaf lists the polygons lying
/// in the splitting plane, so that the inside it stands for can block (they also stay on the negative
/// side). A leaf whose cell is still crossed (depth cap, a non-planar polygon) is not solid.</item>
/// <item>Every internal node has both children, as in real physics BSPs (retail's solid query,
/// BSPNODE::sphere_intersects_solid, follows both unchecked): an empty side is a LEAF with no polygons, not
/// solid, with its own leaf index.</item>
/// <item>Every mesh stops at <see cref="MaxDepth"/> (the reader refuses trees deeper than 256).</item>
/// <item>Every node's sphere contains every vertex of every polygon below it. The root's sphere is the
/// part's broad-phase sphere.</item>
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

    /// <summary>One step of the path from the root: the node's plane and whether the path takes the positive child.</summary>
    private readonly record struct HalfSpace(Plane Plane, bool Pos)
    {
        /// <summary>How far p lies inside this half-space (negative: outside).</summary>
        public float Depth(Vector3 p) => Pos ? PolygonPlane.Distance(Plane, p) : -PolygonPlane.Distance(Plane, p);
    }

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
        return state.Node(Enumerable.Range(0, polys.Length).ToArray(), 0);
    }

    private sealed class BuildState(Poly[] polys, bool closed)
    {
        private int _nextLeaf;
        private readonly List<HalfSpace> _path = [];

        public PhysicsBspNode Node(int[] set, int depth)
        {
            var sphere = Bounds(set);
            Plane? splitter;
            if (closed)
            {
                var crossing = set.Where(i => CrossesCell(polys[i])).ToArray();
                if (crossing.Length == 0) return Leaf(set, sphere, solid: IsInside(CellPoint(set)));
                splitter = depth >= MaxDepth ? null : ChooseSplitter(crossing, set);
            }
            else splitter = set.Length <= MaxLeafPolygons || depth >= MaxDepth ? null : ChooseSplitter(set, set);
            if (splitter is not { } plane) return Leaf(set, sphere, solid: false);

            var pos = new List<int>(set.Length);
            var neg = new List<int>(set.Length);
            var inPlane = new List<int>();
            foreach (var i in set)
            {
                var side = Classify(polys[i], plane, out var onPlane);
                if (side != Side.Neg) pos.Add(i);
                if (side != Side.Pos) neg.Add(i);
                if (onPlane && side == Side.Neg) inPlane.Add(i);
            }

            _path.Add(new HalfSpace(plane, true));
            PhysicsBspNode? posChild = null;
            if (pos.Count > 0) posChild = Node([.. pos], depth + 1);
            else if (closed && inPlane.Count > 0 && IsInside(PointInFrontOf(inPlane)))
                posChild = Leaf([.. inPlane], Bounds([.. inPlane]), solid: true);
            posChild ??= EmptyLeaf(sphere);
            _path[^1] = new HalfSpace(plane, false);
            var negChild = neg.Count > 0 ? Node([.. neg], depth + 1) : EmptyLeaf(sphere);
            _path.RemoveAt(_path.Count - 1);
            return new PhysicsBspNode(BspNodeTypes.ForChildren(pos: true, neg: true), plane, posChild, negChild, sphere, 0, 0, []);
        }

        /// <summary>An empty side: a leaf of its own index, no polygons, not solid, its sphere a point at the parent's centre.</summary>
        private PhysicsBspNode EmptyLeaf(Sphere parent) =>
            new(BspNodeType.Leaf, default, null, null, new Sphere(parent.Center, 0f), _nextLeaf++, 0, []);

        private PhysicsBspNode Leaf(int[] set, Sphere sphere, bool solid) =>
            new(BspNodeType.Leaf, default, null, null, sphere, _nextLeaf++, solid && set.Length > 0 ? 1 : 0, set.Select(i => (ushort)polys[i].Id).ToArray());

        /// <summary>
        /// The splitting plane among the planes of <paramref name="from"/> not yet on the path, scored over
        /// <paramref name="set"/>. Open meshes take only planes that separate something; closed meshes take
        /// any (each split takes one more crossing plane off the cell, so the recursion ends).
        /// </summary>
        private Plane? ChooseSplitter(int[] from, int[] set)
        {
            var candidates = new List<Plane>();
            foreach (var i in from)
                if (polys[i].Plane is { } plane && !candidates.Contains(plane) && !OnPath(plane)) candidates.Add(plane);
            if (candidates.Count > MaxCandidates)
                candidates = Enumerable.Range(0, MaxCandidates).Select(k => candidates[k * candidates.Count / MaxCandidates]).ToList();

            Plane? best = null;
            var bestScore = int.MaxValue;
            foreach (var plane in candidates)
            {
                int pos = 0, neg = 0, spanning = 0;
                foreach (var i in set)
                {
                    switch (Classify(polys[i], plane, out _))
                    {
                        case Side.Pos: pos++; break;
                        case Side.Neg: neg++; break;
                        default: pos++; neg++; spanning++; break;
                    }
                }
                if (!closed && (pos == set.Length || neg == set.Length)) continue;
                var score = 4 * spanning + Math.Abs(pos - neg);
                if (score < bestScore) { bestScore = score; best = plane; }
            }
            return best;
        }

        private bool OnPath(Plane plane)
        {
            foreach (var h in _path)
                if (h.Plane == plane) return true;
            return false;
        }

        private static Side Classify(Poly poly, Plane plane, out bool onPlane)
        {
            float min = float.MaxValue, max = float.MinValue;
            foreach (var p in poly.Points)
            {
                var d = PolygonPlane.Distance(plane, p);
                min = MathF.Min(min, d);
                max = MathF.Max(max, d);
            }
            onPlane = min >= -OnPlaneEpsilon && max <= OnPlaneEpsilon;
            // In the plane: the side behind the polygon (the solid it bounds).
            if (onPlane) return poly.Plane is { } own && PolygonPlane.Dot(own.Normal, plane.Normal) < 0f ? Side.Pos : Side.Neg;
            if (min >= -OnPlaneEpsilon) return Side.Pos;
            if (max <= OnPlaneEpsilon) return Side.Neg;
            return Side.Both;
        }

        /// <summary>Whether part of the polygon lies inside the cell by more than <see cref="OnPlaneEpsilon"/> from every wall.</summary>
        private bool CrossesCell(Poly poly)
        {
            if (poly.Plane is null) return false; // no area: never separates inside from outside
            var points = poly.Points.ToList();
            foreach (var h in _path)
            {
                points = Clip(points, h, OnPlaneEpsilon);
                if (points.Count == 0) return false;
            }
            return true;
        }

        /// <summary>The part of a polygon (Sutherland–Hodgman) lying deeper than <paramref name="margin"/> in the half-space.</summary>
        private static List<Vector3> Clip(List<Vector3> points, HalfSpace h, float margin)
        {
            var result = new List<Vector3>(points.Count + 2);
            for (var k = 0; k < points.Count; k++)
            {
                var a = points[k];
                var b = points[(k + 1) % points.Count];
                var da = h.Depth(a) - margin;
                var db = h.Depth(b) - margin;
                if (da > 0f) result.Add(a);
                if (da > 0f != db > 0f) result.Add(a + (b - a) * (da / (da - db)));
            }
            return result;
        }

        /// <summary>
        /// A point inside the current cell, deepest first: each polygon of the set lying on one of the cell's
        /// walls is clipped to the other walls and its centre moved a little into the cell; the candidate
        /// farthest from every wall wins. Falls back to projecting onto the half-spaces in turn.
        /// </summary>
        private Vector3? CellPoint(int[] set)
        {
            Vector3? best = null;
            var bestDepth = 0f;
            var tried = 0;
            foreach (var i in set)
            {
                if (polys[i].Plane is null) continue;
                for (var k = 0; k < _path.Count && tried < 64; k++)
                {
                    var wall = _path[k];
                    if (polys[i].Points.Any(p => MathF.Abs(PolygonPlane.Distance(wall.Plane, p)) > OnPlaneEpsilon)) continue;
                    var fragment = polys[i].Points.ToList();
                    for (var j = 0; j < _path.Count && fragment.Count > 0; j++)
                        if (j != k) fragment = Clip(fragment, _path[j], OnPlaneEpsilon);
                    if (fragment.Count == 0) continue;
                    tried++;
                    Consider(Offset(Average(fragment), wall), ref best, ref bestDepth);
                }
            }
            return best ?? ProjectedPoint(set);
        }

        /// <summary>A point just in front of the polygons lying in the newest plane, inside the cell and the plane's positive side.</summary>
        private Vector3? PointInFrontOf(List<int> inPlane)
        {
            Vector3? best = null;
            var bestDepth = 0f;
            var wall = _path[^1];
            foreach (var i in inPlane)
            {
                var fragment = polys[i].Points.ToList();
                for (var j = 0; j < _path.Count - 1 && fragment.Count > 0; j++) fragment = Clip(fragment, _path[j], OnPlaneEpsilon);
                if (fragment.Count > 0) Consider(Offset(Average(fragment), wall), ref best, ref bestDepth);
            }
            return best ?? ProjectedPoint([.. inPlane]);
        }

        private static readonly float[] OffsetSteps = [1e-2f, 1e-3f, 2e-4f];

        private static IEnumerable<Vector3> Offset(Vector3 onWall, HalfSpace wall) =>
            OffsetSteps.Select(step => onWall + wall.Plane.Normal * (wall.Pos ? step : -step));

        private void Consider(IEnumerable<Vector3> candidates, ref Vector3? best, ref float bestDepth)
        {
            foreach (var p in candidates)
            {
                var depth = CellDepth(p);
                if (depth > bestDepth) { bestDepth = depth; best = p; }
            }
        }

        /// <summary>The least depth of p in the path's half-spaces (positive: strictly inside the cell).</summary>
        private float CellDepth(Vector3 p)
        {
            var depth = float.MaxValue;
            foreach (var h in _path) depth = MathF.Min(depth, h.Depth(p));
            return depth;
        }

        /// <summary>Alternating projection onto the half-spaces (shrunk by a margin), from the set's box centre.</summary>
        private Vector3? ProjectedPoint(int[] set)
        {
            var min = new Vector3(float.MaxValue);
            var max = new Vector3(float.MinValue);
            foreach (var i in set.Length > 0 ? set : Enumerable.Range(0, polys.Length))
                foreach (var p in polys[i].Points) { min = Vector3.Min(min, p); max = Vector3.Max(max, p); }
            foreach (var margin in (ReadOnlySpan<float>)[1e-3f, 2e-4f])
            {
                var x = (min + max) * 0.5f;
                for (var sweep = 0; sweep < 200; sweep++)
                {
                    var moved = false;
                    foreach (var h in _path)
                    {
                        var depth = h.Depth(x);
                        if (depth >= margin) continue;
                        x += h.Plane.Normal * ((h.Pos ? 1f : -1f) * (margin - depth));
                        moved = true;
                    }
                    if (!moved) break;
                }
                if (CellDepth(x) > 0f) return x;
            }
            return null;
        }

        private static Vector3 Average(List<Vector3> points)
        {
            var sum = Vector3.Zero;
            foreach (var p in points) sum += p;
            return sum / points.Count;
        }

        /// <summary>Inside the mesh: its winding number at p (outward-wound faces) is at least one half.</summary>
        private bool IsInside(Vector3? point) => point is { } p && WindingNumber(p) > 0.5;

        /// <summary>Σ solid angles of the polygons' fan triangles seen from p, over 4π (Van Oosterom–Strackee).</summary>
        private double WindingNumber(Vector3 p)
        {
            double total = 0;
            foreach (var poly in polys)
            {
                var pts = poly.Points;
                for (var j = 1; j + 1 < pts.Length; j++)
                    total += SolidAngle(pts[0] - p, pts[j] - p, pts[j + 1] - p);
            }
            return total / (4 * Math.PI);
        }

        private static double SolidAngle(Vector3 a, Vector3 b, Vector3 c)
        {
            double ax = a.X, ay = a.Y, az = a.Z, bx = b.X, by = b.Y, bz = b.Z, cx = c.X, cy = c.Y, cz = c.Z;
            var la = Math.Sqrt(ax * ax + ay * ay + az * az);
            var lb = Math.Sqrt(bx * bx + by * by + bz * bz);
            var lc = Math.Sqrt(cx * cx + cy * cy + cz * cz);
            var triple = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
            var denominator = la * lb * lc + (ax * bx + ay * by + az * bz) * lc + (ax * cx + ay * cy + az * cz) * lb + (bx * cx + by * cy + bz * cz) * la;
            // Positive when the triangle's normal points away from p: seen from inside, outward faces count +1.
            return 2 * Math.Atan2(triple, denominator);
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
