using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// The BSPNODE and BSPLEAF walks a moving sphere makes, in part space. Every walk uses the node rule
/// dist = N·c + d, reach = r − ε: dist ≥ reach goes positive only, dist ≤ −reach negative only, otherwise
/// positive then negative. A node whose bounding sphere the sphere misses is skipped; an absent child is
/// empty space (as acshadow's placement query treats it). Within a leaf polygons run in stored order.
/// </summary>
internal sealed class BspMovementTraversal(CompiledBsp bsp)
{
    private readonly CompiledBspNode[] _nodes = [.. bsp.Nodes];
    private readonly CompiledPolygon[] _polygons = [.. bsp.Polygons];
    private readonly int[] _leafPolygons = [.. bsp.LeafPolygons];

    public bool IsEmpty => _nodes.Length == 0;

    public CompiledBspNode Root => _nodes[0];

    /// <summary>
    /// BSPNODE/BSPLEAF::sphere_intersects_poly: the first polygon the sphere touches whose normal opposes
    /// <paramref name="movement"/>; <paramref name="touched"/> keeps the last polygon touched at all.
    /// </summary>
    public bool SphereIntersectsPoly(Vector3 center, float radius, Vector3 movement, ref CompiledPolygon? touched) =>
        IntersectsPoly(0, center, radius, movement, ref touched);

    private bool IntersectsPoly(int index, Vector3 center, float radius, Vector3 movement, ref CompiledPolygon? touched)
    {
        if (index < 0) return false;
        ref readonly var node = ref _nodes[index];
        if (node.IsLeaf)
        {
            if (node.ListedPolygonCount == 0 || !SphereBounds.NodeSphereHits(node, center, radius)) return false;
            for (var k = 0; k < node.PolygonCount; k++)
            {
                var polygon = _polygons[_leafPolygons[node.PolygonStart + k]];
                if (PolygonContact.PosHitsSphere(polygon, center, radius, movement, ref touched)) return true;
            }
            return false;
        }
        if (!SphereBounds.NodeSphereHits(node, center, radius)) return false;
        var (pos, neg) = Sides(node, center, radius);
        return (pos && IntersectsPoly(node.Pos, center, radius, movement, ref touched))
            || (neg && IntersectsPoly(node.Neg, center, radius, movement, ref touched));
    }

    /// <summary>
    /// BSPNODE/BSPLEAF::find_walkable: every walkable polygon the sphere touches, in traversal order, may lift
    /// it back along <paramref name="movement"/> onto its plane (the sphere moves as it goes); the last one
    /// that did is returned.
    /// </summary>
    public CompiledPolygon? FindWalkable(SpherePath path, ref Vector3 center, float radius, Vector3 movement, Vector3 up)
    {
        CompiledPolygon? hit = null;
        FindWalkable(0, path, ref center, radius, movement, up, ref hit);
        return hit;
    }

    private void FindWalkable(int index, SpherePath path, ref Vector3 center, float radius, Vector3 movement, Vector3 up, ref CompiledPolygon? hit)
    {
        if (index < 0) return;
        var node = _nodes[index];
        if (node.IsLeaf)
        {
            if (node.ListedPolygonCount == 0 || !SphereBounds.NodeSphereHits(node, center, radius)) return;
            for (var k = 0; k < node.PolygonCount; k++)
            {
                var polygon = _polygons[_leafPolygons[node.PolygonStart + k]];
                if (PolygonContact.WalkableHitsSphere(polygon, path.WalkableAllowance, center, radius, up)
                    && PolygonContact.AdjustSphereToPlane(polygon, path, ref center, radius, movement))
                    hit = polygon;
            }
            return;
        }
        if (!SphereBounds.NodeSphereHits(node, center, radius)) return;
        var (pos, neg) = Sides(node, center, radius);
        if (pos) FindWalkable(node.Pos, path, ref center, radius, movement, up, ref hit);
        if (neg) FindWalkable(node.Neg, path, ref center, radius, movement, up, ref hit);
    }

    /// <summary>BSPNODE/BSPLEAF::hits_walkable: a walkable polygon the sphere touches with half its radius over it.</summary>
    public bool HitsWalkable(float walkableAllowance, Vector3 center, float radius, Vector3 up) => HitsWalkable(0, walkableAllowance, center, radius, up);

    private bool HitsWalkable(int index, float allowance, Vector3 center, float radius, Vector3 up)
    {
        if (index < 0) return false;
        ref readonly var node = ref _nodes[index];
        if (node.IsLeaf)
        {
            if (node.ListedPolygonCount == 0 || !SphereBounds.NodeSphereHits(node, center, radius)) return false;
            for (var k = 0; k < node.PolygonCount; k++)
            {
                var polygon = _polygons[_leafPolygons[node.PolygonStart + k]];
                if (PolygonContact.WalkableHitsSphere(polygon, allowance, center, radius, up)
                    && PolygonContact.CheckWalkable(polygon, center, radius, up, small: true))
                    return true;
            }
            return false;
        }
        if (!SphereBounds.NodeSphereHits(node, center, radius)) return false;
        var (pos, neg) = Sides(node, center, radius);
        return (pos && HitsWalkable(node.Pos, allowance, center, radius, up))
            || (neg && HitsWalkable(node.Neg, allowance, center, radius, up));
    }

    private static (bool Pos, bool Neg) Sides(in CompiledBspNode node, Vector3 center, float radius)
    {
        var dist = MoveMath.Dot(node.Normal, center) + node.D;
        var reach = radius - MovementConstants.Epsilon;
        if (dist >= reach) return (true, false);
        if (dist <= -reach) return (false, true);
        return (true, true);
    }
}
