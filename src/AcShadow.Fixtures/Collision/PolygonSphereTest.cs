using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// Does a sphere touch a polygon? The retail rule (CPolygon::polygon_hits_sphere_precise, reached from
/// BSPLEAF::sphere_intersects_solid via CPolygon::hits_sphere):
/// <list type="number">
/// <item>the sphere, shrunk by <see cref="PhysicsEpsilon"/>, must reach the plane: |dist| ≤ r − ε;</item>
/// <item>it cuts the plane in a disc around the centre's projection; the polygon is hit when that
/// projection lies inside every edge (interior);</item>
/// <item>otherwise, edge by edge: a projection further outside an edge's line than the disc's radius is a
/// miss; one beside the edge segment within the disc is a hit (edge); a vertex inside the disc is a hit.</item>
/// </list>
/// Exact for convex polygons; for non-convex ones the edge order decides, as in retail.
/// </summary>
internal static class PolygonSphereTest
{
    public static bool Touches(CompiledPolygon polygon, Vector3 center, float radius)
    {
        var dist = polygon.Distance(center);
        var rad = radius - PhysicsEpsilon.Value;
        if (MathF.Abs(dist) > rad) return false;

        var discSquared = rad * rad - dist * dist;
        var n = polygon.Normal;
        var contact = new Vector3(center.X - n.X * dist, center.Y - n.Y * dist, center.Z - n.Z * dist);

        var edges = polygon.Edges;
        var inside = true;
        for (var i = 0; i < edges.Length; i++)
        {
            if (PolygonPlane.Dot(Vec.Sub(contact, edges[i].Start), edges[i].Inward) < 0f) { inside = false; break; }
        }
        if (inside) return true;

        for (var i = 0; i < edges.Length; i++)
        {
            ref readonly var edge = ref edges[i];
            var disp = Vec.Sub(contact, edge.Start);
            var side = PolygonPlane.Dot(disp, edge.Inward);
            if (side < 0f)
            {
                if (edge.InwardLengthSquared * discSquared < side * side) return false;
                var along = PolygonPlane.Dot(disp, edge.Vector);
                if (along >= 0f && along <= edge.LengthSquared) return true;
            }
            if (PolygonPlane.Dot(disp, disp) <= discSquared) return true;
        }
        return false;
    }
}
