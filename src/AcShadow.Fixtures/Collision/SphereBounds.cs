using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>Sphere-against-sphere tests the queries share.</summary>
internal static class SphereBounds
{
    /// <summary>CSphere::intersects as the BSP uses it for node rejection: |Δ|² &lt; (R + r)², strict, full radius.</summary>
    public static bool NodeSphereHits(in CompiledBspNode node, Vector3 center, float radius)
    {
        float dx = center.X - node.SphereCenter.X, dy = center.Y - node.SphereCenter.Y, dz = center.Z - node.SphereCenter.Z;
        var sum = node.SphereRadius + radius;
        return dx * dx + dy * dy + dz * dz < sum * sum;
    }

    /// <summary>
    /// CGfxObj::find_obj_collisions' broad phase before the BSP is asked at all: the physics sphere (the
    /// root's) and the query sphere, |Δ|² − (R + r)² &lt; ε. It only matters when the root is a leaf, whose
    /// centre check runs before any sphere test.
    /// </summary>
    public static bool BroadPhaseHits(in CompiledBspNode root, Vector3 center, float radius)
    {
        float dx = root.SphereCenter.X - center.X, dy = root.SphereCenter.Y - center.Y, dz = root.SphereCenter.Z - center.Z;
        var sum = root.SphereRadius + radius;
        return dx * dx + dy * dy + dz * dz - sum * sum < PhysicsEpsilon.Value;
    }

    public static bool IsValidProbe(Vector3 center, float radius) => Vec.IsFinite(center) && float.IsFinite(radius) && radius >= 0f;
}
