using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>A CylSphere in entity space, its base at <paramref name="baseCenter"/>, as a query (<see cref="CylinderSphereTest"/>).</summary>
internal sealed class CylinderShapeQuery(Vector3 baseCenter, float radius, float height) : ISphereOverlap
{
    public bool Overlaps(Vector3 c, float r) => SphereBounds.IsValidProbe(c, r) && CylinderSphereTest.Touches(baseCenter, radius, height, c, r);
}
