using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>A Setup sphere in entity space as a query (<see cref="SphereSphereTest"/>).</summary>
internal sealed class SphereShapeQuery(Vector3 center, float radius) : ISphereOverlap
{
    public bool Overlaps(Vector3 c, float r) => SphereBounds.IsValidProbe(c, r) && SphereSphereTest.Touches(center, radius, c, r);
}
