using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// The CPolygon tests a moving sphere needs beyond the static contact test (<see cref="PolygonSphereTest"/>,
/// polygon_hits_sphere_precise): which way the polygon faces the movement, whether it is walkable, and
/// where a sphere pushed along a movement comes to rest on its plane. All in part space.
/// </summary>
internal static class PolygonContact
{
    /// <summary>
    /// CPolygon::pos_hits_sphere: a touched polygon is remembered in <paramref name="touched"/> whatever its
    /// facing, but is a hit only when its normal opposes the movement.
    /// </summary>
    public static bool PosHitsSphere(CompiledPolygon polygon, Vector3 center, float radius, Vector3 movement, ref CompiledPolygon? touched)
    {
        var hit = PolygonSphereTest.Touches(polygon, center, radius);
        if (hit) touched = polygon;
        if (MoveMath.Dot(movement, polygon.Normal) >= 0f) return false;
        return hit;
    }

    // CPolygon::walkable_hits_sphere
    public static bool WalkableHitsSphere(CompiledPolygon polygon, float walkableAllowance, Vector3 center, float radius, Vector3 up)
    {
        if (MoveMath.Dot(up, polygon.Normal) <= walkableAllowance) return false;
        return PolygonSphereTest.Touches(polygon, center, radius);
    }

    /// <summary>
    /// CPolygon::adjust_sphere_to_plane: moves the sphere back along <paramref name="movement"/> until it rests
    /// on the plane, if that keeps walk_interp inside [−0.5, walk_interp); lowers walk_interp to match.
    /// </summary>
    public static bool AdjustSphereToPlane(CompiledPolygon polygon, SpherePath path, ref Vector3 center, float radius, Vector3 movement)
    {
        var dpPos = MoveMath.Dot(center, polygon.Normal) + polygon.D;
        var dpMove = MoveMath.Dot(movement, polygon.Normal);
        float dist;
        if (dpMove <= MovementConstants.Epsilon)
        {
            if (dpMove >= -MovementConstants.Epsilon) return false;
            dist = dpPos - radius;
        }
        else
        {
            dist = -radius - dpPos;
        }
        var iDist = dist / dpMove;
        var interp = (1f - iDist) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < MovementConstants.PolygonInterpFloor) return false;
        center -= MoveMath.Scale(movement, iDist);
        path.WalkInterp = interp;
        return true;
    }

    /// <summary>
    /// CPolygon::check_walkable: is the sphere's centre, dropped along <paramref name="up"/> onto the plane,
    /// within r (within r/2 when <paramref name="small"/>) of the polygon?
    /// </summary>
    public static bool CheckWalkable(CompiledPolygon polygon, Vector3 center, float radius, Vector3 up, bool small)
    {
        var angleUp = MoveMath.Dot(polygon.Normal, up);
        if (angleUp < MovementConstants.Epsilon) return false;
        var dropped = center - MoveMath.Scale(up, (MoveMath.Dot(polygon.Normal, center) + polygon.D) / angleUp);
        var radiusSquared = radius * radius;
        if (small) radiusSquared *= 0.25f;
        foreach (var edge in polygon.Edges)
        {
            var disp = dropped - edge.Start;
            var side = MoveMath.Dot(disp, edge.Inward);
            if (side < 0f)
            {
                if (edge.InwardLengthSquared * radiusSquared < side * side) return false;
                var along = MoveMath.Dot(disp, edge.Vector);
                return along >= 0f && along <= edge.LengthSquared;
            }
            if (MoveMath.LengthSquared(disp) <= radiusSquared) return true;
        }
        return true;
    }

    /// <summary>CPolygon::find_crossed_edge: the inward normal of the first edge the dropped centre lies outside of.</summary>
    public static bool FindCrossedEdge(CompiledPolygon polygon, Vector3 center, Vector3 up, out Vector3 normal)
    {
        normal = Vector3.Zero;
        var angleUp = MoveMath.Dot(polygon.Normal, up);
        if (MathF.Abs(angleUp) < MovementConstants.Epsilon) return false;
        var dropped = center - MoveMath.Scale(up, (MoveMath.Dot(polygon.Normal, center) + polygon.D) / angleUp);
        foreach (var edge in polygon.Edges)
        {
            var disp = dropped - edge.Start;
            if (MoveMath.Dot(disp, edge.Inward) < 0f)
            {
                normal = MoveMath.Scale(edge.Inward, 1f / MathF.Sqrt(edge.InwardLengthSquared));
                return true;
            }
        }
        return false;
    }
}
