using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A vertical cylinder (base centre, radius, height) against a sphere, as retail's placement test does it
/// (CCylSphere::intersects_sphere → collides_with_sphere): the horizontal distance from the axis at most
/// R − ε + r, and r − ε + h/2 ≥ |h/2 − (z − base z)|. A box in profile: no rounding at the rims.
/// </summary>
internal static class CylinderSphereTest
{
    public static bool Touches(Vector3 baseCenter, float cylinderRadius, float height, Vector3 center, float radius)
    {
        float dx = center.X - baseCenter.X, dy = center.Y - baseCenter.Y, dz = center.Z - baseCenter.Z;
        var radsum = cylinderRadius - PhysicsEpsilon.Value + radius;
        if (!(dx * dx + dy * dy <= radsum * radsum)) return false;
        var half = height * 0.5f;
        return radius - PhysicsEpsilon.Value + half >= MathF.Abs(half - dz);
    }
}
