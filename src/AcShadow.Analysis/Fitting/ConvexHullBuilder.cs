using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Fitting;

/// <summary>
/// The convex hull of a part's physics vertices: an incremental hull in double (a point within a tolerance
/// of a face counts as on it, so vertices on a subdivided face or an edge add nothing), coplanar
/// neighbouring triangles merged into one convex polygon per face. Each face takes the retail plane of a
/// physics polygon lying in it when there is one (so a hull that is the part itself answers with the
/// part's own plane bits), else the plane CPolygon::make_plane gives its corners. Points that all lie in
/// one plane give a flat hull: the outline wound both ways. Fewer than three non-collinear points, or a set
/// whose hull float rounding cannot settle (the faces a point sees are not one patch): null.
/// </summary>
internal static class ConvexHullBuilder
{
    /// <summary>Relative tolerance: a point closer than this × the points' extent to a face is on it.</summary>
    public const double RelativeTolerance = 1e-6;

    private sealed class Face(int a, int b, int c, Vector3d n, double offset)
    {
        public readonly int A = a, B = b, C = c;
        public readonly Vector3d N = n;
        public readonly double Offset = offset;
        public bool Alive = true;
        public double Distance(Vector3d p) => N.Dot(p) + Offset;
    }

    public static ConvexPolytope? Build(IReadOnlyList<Vector3> input, IReadOnlyList<Plane> retailPlanes)
    {
        var points = input.Where(v => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z)).Distinct().ToArray();
        if (points.Length < 3) return null;
        var p = points.Select(v => new Vector3d(v.X, v.Y, v.Z)).ToArray();
        var lo = p[0];
        var hi = p[0];
        foreach (var v in p) { lo = Vector3d.Min(lo, v); hi = Vector3d.Max(hi, v); }
        var extent = Math.Max(hi.X - lo.X, Math.Max(hi.Y - lo.Y, hi.Z - lo.Z));
        var tol = RelativeTolerance * Math.Max(extent, 1e-3);

        var i0 = 0;
        for (var i = 1; i < p.Length; i++) if (p[i].X < p[i0].X) i0 = i;
        var i1 = ArgMax(p, v => (v - p[i0]).Length());
        if ((p[i1] - p[i0]).Length() <= tol) return null;
        var axis = (p[i1] - p[i0]).Normalized();
        var i2 = ArgMax(p, v => (v - p[i0]).Cross(axis).Length());
        if ((p[i2] - p[i0]).Cross(axis).Length() <= tol) return null;
        var normal = (p[i1] - p[i0]).Cross(p[i2] - p[i0]).Normalized();
        var i3 = ArgMax(p, v => Math.Abs(normal.Dot(v - p[i0])));
        if (Math.Abs(normal.Dot(p[i3] - p[i0])) <= tol) return Flat(points, p, normal, retailPlanes, tol);

        var faces = new List<Face>();
        var edges = new Dictionary<(int, int), int>();
        var inside = (p[i0] + p[i1] + p[i2] + p[i3]) * 0.25;
        void Add(int a, int b, int c)
        {
            var n = (p[b] - p[a]).Cross(p[c] - p[a]);
            if (n.Dot(p[a] - inside) < 0) { (b, c) = (c, b); n = (p[b] - p[a]).Cross(p[c] - p[a]); }
            n = n.Normalized();
            faces.Add(new Face(a, b, c, n, -n.Dot(p[a])));
            var f = faces.Count - 1;
            edges[(a, b)] = f;
            edges[(b, c)] = f;
            edges[(c, a)] = f;
        }
        Add(i0, i1, i2);
        Add(i0, i1, i3);
        Add(i1, i2, i3);
        Add(i0, i2, i3);

        var visible = new List<int>();
        var horizon = new List<(int, int)>();
        for (var i = 0; i < p.Length; i++)
        {
            if (i == i0 || i == i1 || i == i2 || i == i3) continue;
            // Near a flat spot the faces a point sees may not be one patch (a face flat with it, within the
            // tolerance, parts two it sees), so their rim is not one loop and the surface would tear. Such a point
            // is asked again with other margins (below); one still torn at every margin leaves the part without a
            // hull rather than with a torn one.
            var settled = false;
            foreach (var margin in Margins)
            {
                Visible(faces, p[i], tol * margin, visible);
                if (visible.Count == 0) { settled = true; break; }
                FillHoles(faces, edges, visible);
                Rim(faces, edges, visible, horizon);
                if (IsOneLoop(horizon)) { settled = true; break; }
            }
            if (!settled || faces.Count + horizon.Count > MaxFaces(p.Length)) return null;
            if (visible.Count == 0) continue;
            foreach (var f in visible)
            {
                faces[f].Alive = false;
                foreach (var e in EdgesOf(faces[f]))
                    if (edges.TryGetValue(e, out var owner) && owner == f) edges.Remove(e);
            }
            foreach (var (a, b) in horizon)
            {
                // Wound like the face it replaces, so it faces out without a reference point.
                var n = (p[b] - p[a]).Cross(p[i] - p[a]).Normalized();
                faces.Add(new Face(a, b, i, n, -n.Dot(p[a])));
                var f = faces.Count - 1;
                edges[(a, b)] = f;
                edges[(b, i)] = f;
                edges[(i, a)] = f;
            }
        }
        return Merge(points, p, faces.Where(f => f.Alive).ToList(), edges, faces, retailPlanes, tol);
    }

    /// <summary>
    /// Margins (× the tolerance) a point's visible faces are asked with, until their rim is one loop: first
    /// the tolerance; then also the faces it lies in (−1: two seen faces that met only at a corner across a
    /// face flat with the point join up); then wider ones (a face seen by a hair drops out).
    /// </summary>
    private static readonly double[] Margins = [1, -1, 10, 100];

    private static void Visible(List<Face> faces, Vector3d point, double margin, List<int> visible)
    {
        visible.Clear();
        for (var f = 0; f < faces.Count; f++)
            if (faces[f].Alive && faces[f].Distance(point) > margin) visible.Add(f);
    }

    /// <summary>
    /// A face the point does not see whose every neighbour it sees (a sliver left flat or flipped by
    /// rounding) would leave a second loop in the rim: it goes with its neighbours.
    /// </summary>
    private static void FillHoles(List<Face> faces, Dictionary<(int, int), int> edges, List<int> visible)
    {
        var seen = visible.ToHashSet();
        for (var changed = true; changed;)
        {
            changed = false;
            foreach (var f in seen.ToArray())
                foreach (var (a, b) in EdgesOf(faces[f]))
                {
                    if (!edges.TryGetValue((b, a), out var other) || seen.Contains(other) || !faces[other].Alive) continue;
                    if (EdgesOf(faces[other]).All(e => edges.TryGetValue((e.Item2, e.Item1), out var n) && seen.Contains(n)))
                    {
                        seen.Add(other);
                        visible.Add(other);
                        changed = true;
                    }
                }
        }
    }

    /// <summary>The edges of the visible faces whose other side is not visible: where the new faces attach.</summary>
    private static void Rim(List<Face> faces, Dictionary<(int, int), int> edges, List<int> visible, List<(int, int)> rim)
    {
        rim.Clear();
        var seen = visible.ToHashSet();
        foreach (var f in visible)
            foreach (var (a, b) in EdgesOf(faces[f]))
                if (!edges.TryGetValue((b, a), out var twin) || !seen.Contains(twin)) rim.Add((a, b));
    }

    /// <summary>A hull of n points has at most 2n − 4 faces; the faces list keeps the dead ones too, so this allows many times that.</summary>
    private static int MaxFaces(int points) => 64 * points + 1024;

    /// <summary>True when every rim vertex starts exactly one edge and ends exactly one, and the edges form one cycle.</summary>
    private static bool IsOneLoop(List<(int A, int B)> rim)
    {
        if (rim.Count < 3) return false;
        var next = new Dictionary<int, int>(rim.Count);
        foreach (var (a, b) in rim) if (!next.TryAdd(a, b)) return false;
        // Walk from the first vertex: one cycle through all of them comes back exactly at the last step.
        var start = rim[0].A;
        var at = start;
        for (var k = 1; k <= rim.Count; k++)
        {
            if (!next.TryGetValue(at, out at)) return false;
            if (at == start) return k == rim.Count;
        }
        return false;
    }

    private static IEnumerable<(int, int)> EdgesOf(Face f) => [(f.A, f.B), (f.B, f.C), (f.C, f.A)];

    /// <summary>Neighbouring triangles in one plane become one face: the convex outline of their corners.</summary>
    private static ConvexPolytope Merge(Vector3[] points, Vector3d[] p, List<Face> alive, Dictionary<(int, int), int> edges, List<Face> all,
        IReadOnlyList<Plane> retailPlanes, double tol)
    {
        var index = new Dictionary<Face, int>();
        for (var i = 0; i < alive.Count; i++) index[alive[i]] = i;
        var parent = Enumerable.Range(0, alive.Count).ToArray();
        int Find(int x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; }
        for (var i = 0; i < alive.Count; i++)
        {
            var f = alive[i];
            foreach (var (a, b) in EdgesOf(f))
            {
                if (!edges.TryGetValue((b, a), out var t) || !index.TryGetValue(all[t], out var j)) continue;
                var g = alive[j];
                var third = g.A != a && g.A != b ? g.A : g.B != a && g.B != b ? g.B : g.C;
                if (f.N.Dot(g.N) > 0.99 && Math.Abs(f.Distance(p[third])) <= tol) parent[Find(i)] = Find(j);
            }
        }
        var polygons = new List<Vector3[]>();
        var normals = new List<Vector3d>();
        foreach (var group in Enumerable.Range(0, alive.Count).GroupBy(Find).OrderBy(g => g.Key))
        {
            var n = new Vector3d(0, 0, 0);
            var corners = new SortedSet<int>();
            foreach (var k in group)
            {
                var f = alive[k];
                n += (p[f.B] - p[f.A]).Cross(p[f.C] - p[f.A]);
                corners.Add(f.A); corners.Add(f.B); corners.Add(f.C);
            }
            n = n.Normalized();
            polygons.Add(Outline(corners.ToArray(), p, n).Select(i => points[i]).ToArray());
            normals.Add(n);
        }
        return Assemble(polygons, normals, retailPlanes, tol);
    }

    private static ConvexPolytope? Flat(Vector3[] points, Vector3d[] p, Vector3d normal, IReadOnlyList<Plane> retailPlanes, double tol)
    {
        var outline = Outline(Enumerable.Range(0, p.Length).ToArray(), p, normal).Select(i => points[i]).ToArray();
        if (outline.Length < 3) return null;
        return Assemble([outline, outline.Reverse().ToArray()], [normal, normal * -1], retailPlanes, tol);
    }

    /// <summary>The convex outline of points lying in a plane, counter-clockwise seen from the normal's side (Andrew's monotone chain).</summary>
    private static int[] Outline(int[] ids, Vector3d[] p, Vector3d n)
    {
        var u = (Math.Abs(n.X) < 0.9 ? new Vector3d(1, 0, 0) : new Vector3d(0, 1, 0)).Cross(n).Normalized();
        var v = n.Cross(u);
        var pts = ids.Select(i => (Id: i, X: u.Dot(p[i]), Y: v.Dot(p[i]))).OrderBy(t => t.X).ThenBy(t => t.Y).ThenBy(t => t.Id).ToArray();
        if (pts.Length < 3) return pts.Select(t => t.Id).ToArray();
        static double Cross((int, double X, double Y) o, (int, double X, double Y) a, (int, double X, double Y) b) => (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
        var hull = new List<(int Id, double X, double Y)>();
        foreach (var pass in new[] { pts, pts.Reverse().ToArray() })
        {
            var start = hull.Count;
            foreach (var t in pass)
            {
                while (hull.Count >= start + 2 && Cross(hull[^2], hull[^1], t) <= 1e-12 * (1 + Math.Abs(t.X) + Math.Abs(t.Y))) hull.RemoveAt(hull.Count - 1);
                hull.Add(t);
            }
            hull.RemoveAt(hull.Count - 1);
        }
        return hull.Select(t => t.Id).ToArray();
    }

    private static ConvexPolytope Assemble(List<Vector3[]> outlines, List<Vector3d> normals, IReadOnlyList<Plane> retailPlanes, double tol)
    {
        var faces = new List<CompiledPolygon>();
        var vertices = new List<Vector3>();
        var known = new HashSet<Vector3>();
        for (var k = 0; k < outlines.Count; k++)
        {
            var outline = outlines[k];
            if (outline.Length < 3) continue;
            var plane = Snap(outline, normals[k], retailPlanes, tol) ?? PolygonPlane.Compute(outline);
            if (plane is not { } pl || !(pl.Normal.X * normals[k].X + pl.Normal.Y * normals[k].Y + pl.Normal.Z * normals[k].Z > 0)) continue;
            faces.Add(new CompiledPolygon(faces.Count, pl, outline));
            foreach (var v in outline) if (known.Add(v)) vertices.Add(v);
        }
        return new ConvexPolytope(vertices, faces);
    }

    /// <summary>A physics polygon's retail plane the face lies in, if any.</summary>
    private static Plane? Snap(Vector3[] outline, Vector3d n, IReadOnlyList<Plane> retailPlanes, double tol)
    {
        foreach (var plane in retailPlanes)
        {
            if (plane.Normal.X * n.X + plane.Normal.Y * n.Y + plane.Normal.Z * n.Z < 1 - 1e-6) continue;
            if (outline.All(v => Math.Abs((double)PolygonPlane.Distance(plane, v)) <= Math.Max(tol, 1e-6))) return plane;
        }
        return null;
    }

    private static int ArgMax(Vector3d[] p, Func<Vector3d, double> score)
    {
        var best = 0;
        var top = double.NegativeInfinity;
        for (var i = 0; i < p.Length; i++)
        {
            var s = score(p[i]);
            if (s > top) { top = s; best = i; }
        }
        return best;
    }
}
