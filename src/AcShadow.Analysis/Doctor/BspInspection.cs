using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The retail BSP claims checked on one GfxObj's PhysicsBSP (retail-collision.md, "The BSP"):
/// each internal node's plane is <c>CPolygon::make_plane</c> of a polygon lying in it, bit for bit; every
/// internal node has both children (<c>BSPNODE::sphere_intersects_solid</c> follows both unchecked); a solid
/// leaf holds polygons; leaves name polygons the GfxObj has; every node's bounding sphere holds its subtree.
/// </summary>
internal static class BspInspection
{
    /// <summary>A vertex this close to a node's plane (metres) lies in it: the forge's and float noise's scale, far below any real feature.</summary>
    public const float InPlaneTolerance = 1e-3f;

    /// <summary>
    /// A vertex may lie this far outside a node's sphere before the sphere test can miss a contact: half of
    /// retail's EPSILON (0.0002), which the sphere-vs-polygon test gives away.
    /// </summary>
    public const double SphereSlackMetres = 0.0001;

    public static void Inspect(GfxObj gfx, DoctorTallies t)
    {
        if (gfx.PhysicsBsp is not { } root) return;
        t.BspGfxObjs.Add();
        var polygons = new Dictionary<ushort, Vector3[]?>(gfx.PhysicsPolygons.Count);
        var planes = new HashSet<(int, int, int, int)>();
        var resolved = new List<(Vector3[] Points, Plane Plane)>(gfx.PhysicsPolygons.Count);
        long missingVertices = 0;
        foreach (var (key, polygon) in gfx.PhysicsPolygons)
        {
            var points = Points(gfx, polygon);
            if (points is null) missingVertices++;
            polygons[key] = points;
            if (points is not null && PolygonPlane.Compute(points) is { } plane)
            {
                planes.Add(Bits(plane));
                resolved.Add((points, plane));
            }
        }
        t.PolygonVertexMissing.Add(gfx.Id, missingVertices);

        var scan = new TreeScan(polygons, planes, resolved);
        scan.Visit(root, 0);
        scan.AddTo(gfx.Id, t);
    }

    private static Vector3[]? Points(GfxObj gfx, Polygon polygon)
    {
        var points = new Vector3[polygon.VertexIds.Count];
        for (var i = 0; i < points.Length; i++)
            if (!gfx.Vertices.TryGetValue(unchecked((ushort)polygon.VertexIds[i]), out points[i])) return null;
        return points;
    }

    private static (int, int, int, int) Bits(Plane p) =>
        (BitConverter.SingleToInt32Bits(p.Normal.X), BitConverter.SingleToInt32Bits(p.Normal.Y),
         BitConverter.SingleToInt32Bits(p.Normal.Z), BitConverter.SingleToInt32Bits(p.D));

    /// <summary>One tree's walk: counts kept locally and added to the shared tallies once per GfxObj.</summary>
    private sealed class TreeScan(Dictionary<ushort, Vector3[]?> polygons, HashSet<(int, int, int, int)> planes, List<(Vector3[] Points, Plane Plane)> resolved)
    {
        /// <summary>The decoder refuses trees deeper than 256 levels.</summary>
        private const int MaxDepth = 258;

        // The spheres of the nodes from the root down to the one being visited, and the farthest squared
        // distance from each centre of any vertex below it so far: a vertex updates every sphere above it.
        private readonly Vector3[] _centres = new Vector3[MaxDepth];
        private readonly double[] _farthest = new double[MaxDepth];

        private long _internal, _leaves, _oneChild, _reproduced, _missed, _negated, _withoutPolygon;
        private long _solidWithPolygons, _solidEmpty, _openWithPolygons, _openEmpty, _oddSolid, _polygonRefs, _missingPolygons;
        private long _spheres, _containing, _withinSlack, _tooSmall, _maxExcessNanometres;
        private readonly List<long> _ulps = [];

        public void Visit(PhysicsBspNode node, int depth)
        {
            _centres[depth] = node.BoundingSphere.Center;
            _farthest[depth] = -1;
            if (node.IsLeaf)
            {
                _leaves++;
                foreach (var p in node.Polygons)
                {
                    _polygonRefs++;
                    if (!polygons.TryGetValue(p, out var points)) _missingPolygons++;
                    else if (points is not null) Reach(points, depth);
                }
                var has = node.Polygons.Count > 0;
                switch (node.Solid)
                {
                    case 1 when has: _solidWithPolygons++; break;
                    case 1: _solidEmpty++; break;
                    case 0 when has: _openWithPolygons++; break;
                    case 0: _openEmpty++; break;
                    default: _oddSolid++; break;
                }
            }
            else
            {
                _internal++;
                if (node.Pos is null || node.Neg is null) _oneChild++;
                CheckPlane(node.SplittingPlane);
                if (node.Pos is { } pos) Visit(pos, depth + 1);
                if (node.Neg is { } neg) Visit(neg, depth + 1);
            }
            CheckSphere(node.BoundingSphere.Radius, depth);
        }

        private void Reach(Vector3[] points, int depth)
        {
            foreach (var v in points)
                for (var k = 0; k <= depth; k++)
                {
                    double dx = v.X - _centres[k].X, dy = v.Y - _centres[k].Y, dz = v.Z - _centres[k].Z;
                    var d = dx * dx + dy * dy + dz * dz;
                    if (d > _farthest[k] || double.IsNaN(d)) _farthest[k] = d;
                }
        }

        private void CheckPlane(Plane stored)
        {
            if (planes.Contains(Bits(stored))) { _reproduced++; return; }
            _missed++;
            // The nearest make_plane among the polygons lying in the stored plane, in ULPs of its worst component.
            long best = long.MaxValue;
            var negated = false;
            foreach (var (points, plane) in resolved)
            {
                if (!LiesIn(points, stored)) continue;
                if (Bits(Negate(plane)) == Bits(stored)) { negated = true; break; }
                best = Math.Min(best, Ulps(plane, stored));
            }
            if (negated) _negated++;
            else if (best == long.MaxValue) _withoutPolygon++;
            else _ulps.Add(best);
        }

        private static Plane Negate(Plane p) => new(-p.Normal, -p.D);

        private static long Ulps(Plane a, Plane b) => Math.Max(
            Math.Max(UlpHistogram.Distance(a.Normal.X, b.Normal.X), UlpHistogram.Distance(a.Normal.Y, b.Normal.Y)),
            Math.Max(UlpHistogram.Distance(a.Normal.Z, b.Normal.Z), UlpHistogram.Distance(a.D, b.D)));

        private static bool LiesIn(Vector3[] points, Plane plane)
        {
            foreach (var p in points)
                if (!(MathF.Abs(PolygonPlane.Distance(plane, p)) <= InPlaneTolerance)) return false;
            return true;
        }

        /// <summary>Whether the node's sphere holds every vertex below it; a node with no polygons below has nothing to hold.</summary>
        private void CheckSphere(float radius, int depth)
        {
            var farthest = _farthest[depth];
            if (farthest < 0) return;
            _spheres++;
            var worst = Math.Sqrt(farthest) - radius;
            if (double.IsNaN(worst)) { _tooSmall++; return; }
            if (worst <= 0) { _containing++; return; }
            _maxExcessNanometres = Math.Max(_maxExcessNanometres, double.IsFinite(worst) ? (long)Math.Ceiling(Math.Min(worst, 1e6) * 1e9) : long.MaxValue);
            if (worst <= SphereSlackMetres) _withinSlack++;
            else _tooSmall++;
        }

        public void AddTo(uint id, DoctorTallies t)
        {
            t.InternalNodes.Add(_internal);
            t.Leaves.Add(_leaves);
            t.OneChildNode.Add(id, _oneChild);
            t.PlanesReproduced.Add(_reproduced);
            t.PlaneNotReproduced.Add(id, _missed);
            t.PlanesNegated.Add(_negated);
            t.PlanesWithoutPolygon.Add(_withoutPolygon);
            foreach (var u in _ulps) t.PlaneUlps.Add(u);
            t.SolidWithPolygons.Add(_solidWithPolygons);
            t.SolidEmpty.Add(_solidEmpty);
            t.OpenWithPolygons.Add(_openWithPolygons);
            t.OpenEmpty.Add(_openEmpty);
            t.SolidLeafEmpty.Add(id, _solidEmpty);
            t.SolidFlagOddValue.Add(id, _oddSolid);
            t.LeafPolygonRefs.Add(_polygonRefs);
            t.LeafPolygonMissing.Add(id, _missingPolygons);
            t.SpheresChecked.Add(_spheres);
            t.SpheresExactlyContaining.Add(_containing);
            t.SpheresWithinSlack.Add(_withinSlack);
            t.SphereTooSmall.Add(id, _tooSmall);
            if (_maxExcessNanometres > 0) t.ObserveExcess(_maxExcessNanometres);
        }
    }
}
