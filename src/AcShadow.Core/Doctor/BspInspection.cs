using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Doctor;

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

        var scan = new TreeScan(t, polygons, planes, resolved);
        scan.Visit(root);
        t.OneChildNode.Add(gfx.Id, scan.OneChild);
        t.PlaneNotReproduced.Add(gfx.Id, scan.PlanesMissed);
        t.SolidLeafEmpty.Add(gfx.Id, scan.SolidEmpty);
        t.SolidFlagOddValue.Add(gfx.Id, scan.OddSolid);
        t.LeafPolygonMissing.Add(gfx.Id, scan.MissingPolygons);
        t.SphereTooSmall.Add(gfx.Id, scan.SpheresTooSmall);
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

    private sealed class TreeScan(DoctorTallies t, Dictionary<ushort, Vector3[]?> polygons,
        HashSet<(int, int, int, int)> planes, List<(Vector3[] Points, Plane Plane)> resolved)
    {
        public long OneChild, PlanesMissed, SolidEmpty, OddSolid, MissingPolygons, SpheresTooSmall;

        /// <summary>Checks the subtree and returns the polygons its leaves hold (for the spheres above it).</summary>
        public List<Vector3[]> Visit(PhysicsBspNode node)
        {
            List<Vector3[]> held;
            if (node.IsLeaf)
            {
                t.Leaves.Add();
                held = new List<Vector3[]>(node.Polygons.Count);
                foreach (var p in node.Polygons)
                {
                    t.LeafPolygonRefs.Add();
                    if (!polygons.TryGetValue(p, out var points)) MissingPolygons++;
                    else if (points is not null) held.Add(points);
                }
                var has = node.Polygons.Count > 0;
                switch (node.Solid)
                {
                    case 1 when has: t.SolidWithPolygons.Add(); break;
                    case 1: t.SolidEmpty.Add(); SolidEmpty++; break;
                    case 0 when has: t.OpenWithPolygons.Add(); break;
                    case 0: t.OpenEmpty.Add(); break;
                    default: OddSolid++; break;
                }
            }
            else
            {
                t.InternalNodes.Add();
                if (node.Pos is null || node.Neg is null) OneChild++;
                CheckPlane(node.SplittingPlane);
                held = node.Pos is { } pos ? Visit(pos) : [];
                if (node.Neg is { } neg) held.AddRange(Visit(neg));
            }
            CheckSphere(node.BoundingSphere, held);
            return held;
        }

        private void CheckPlane(Plane stored)
        {
            if (planes.Contains(Bits(stored))) { t.PlanesReproduced.Add(); return; }
            PlanesMissed++;
            // The nearest make_plane among the polygons lying in the stored plane, in ULPs of its worst component.
            long best = long.MaxValue;
            var negated = false;
            foreach (var (points, plane) in resolved)
            {
                if (!LiesIn(points, stored)) continue;
                if (Bits(Negate(plane)) == Bits(stored)) { negated = true; break; }
                best = Math.Min(best, Ulps(plane, stored));
            }
            if (negated) t.PlanesNegated.Add();
            else if (best == long.MaxValue) t.PlanesWithoutPolygon.Add();
            else t.PlaneUlps.Add(best);
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

        private void CheckSphere(Sphere sphere, List<Vector3[]> held)
        {
            if (held.Count == 0) return;
            t.SpheresChecked.Add();
            var worst = double.NegativeInfinity;
            foreach (var points in held)
                foreach (var v in points)
                {
                    double dx = v.X - sphere.Center.X, dy = v.Y - sphere.Center.Y, dz = v.Z - sphere.Center.Z;
                    worst = Math.Max(worst, Math.Sqrt(dx * dx + dy * dy + dz * dz) - sphere.Radius);
                }
            if (double.IsNaN(worst)) { SpheresTooSmall++; return; }
            if (worst <= 0) { t.SpheresExactlyContaining.Add(); return; }
            t.ObserveExcess(double.IsFinite(worst) ? (long)Math.Ceiling(Math.Min(worst, 1e6) * 1e9) : long.MaxValue);
            if (worst <= SphereSlackMetres) t.SpheresWithinSlack.Add();
            else SpheresTooSmall++;
        }
    }
}
