using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>A Setup sphere against a query sphere, retail's placement test (CSphere::intersects_sphere): |Δ|² ≤ (R + r − ε)².</summary>
internal static class SphereSphereTest
{
    public static bool Touches(Vector3 sphereCenter, float sphereRadius, Vector3 center, float radius)
    {
        var radsum = radius + sphereRadius - PhysicsEpsilon.Value;
        return Vec.DistanceSquared(center, sphereCenter) <= radsum * radsum;
    }
}
