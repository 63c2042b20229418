using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Collision;

/// <summary>
/// A second way to build PhysicsBSPs for tests, unlike the forge's: a polygon lying in a splitting plane
/// goes to both children, splitting goes on until every polygon in a set has had its plane on the path,
/// and every leaf keeps the polygons that bound it; a leaf reached through a negative child is solid. So
/// solid leaves hold polygons and the retail centre check is exercised.
/// </summary>
public static class TestBspBuilder
{
    private const float OnPlane = 1e-4f;

    public static PhysicsBspNode Build(TestMesh mesh)
    {
        var points = mesh.Polygons.Select(p => p.Select(i => mesh.Vertices[i]).ToArray()).ToArray();
        var planes = points.Select(p => PolygonPlane.Compute(p)).ToArray();
        var leafIndex = 0;
        var usable = Enumerable.Range(0, points.Length).Where(i => planes[i] is not null).ToArray();
        return Node(usable, [], false);

        PhysicsBspNode Node(int[] set, HashSet<int> used, bool cameFromNeg)
        {
            var sphere = Bounds(set);
            var splitter = set.FirstOrDefault(i => !used.Contains(i), -1);
            if (splitter < 0)
                return new PhysicsBspNode(BspNodeType.Leaf, default, null, null, sphere, leafIndex++, cameFromNeg && set.Length > 0 ? 1 : 0, set.Select(i => (ushort)i).ToArray());
            var plane = planes[splitter]!.Value;
            var pos = new List<int>();
            var neg = new List<int>();
            var nowUsed = new HashSet<int>(used) { splitter };
            foreach (var i in set)
            {
                var d = points[i].Select(p => PolygonPlane.Distance(plane, p)).ToArray();
                var on = d.All(x => MathF.Abs(x) <= OnPlane);
                if (on) nowUsed.Add(i);
                if (on || d.Max() > OnPlane) pos.Add(i);
                if (on || d.Min() < -OnPlane) neg.Add(i);
            }
            var posChild = Node([.. pos], nowUsed, false);
            var negChild = Node([.. neg], nowUsed, true);
            return new PhysicsBspNode(BspNodeType.BPIN, plane, posChild, negChild, sphere, 0, 0, []);
        }

        Sphere Bounds(int[] set)
        {
            var all = set.SelectMany(i => points[i]).ToArray();
            if (all.Length == 0) return new Sphere(Vector3.Zero, 0f);
            var min = all.Aggregate(Vector3.Min);
            var max = all.Aggregate(Vector3.Max);
            var center = (min + max) * 0.5f;
            var radius = all.Max(p => (double)Vector3.Distance(p, center));
            return new Sphere(center, (float)(radius * (1 + 1e-6) + 1e-6));
        }
    }
}
