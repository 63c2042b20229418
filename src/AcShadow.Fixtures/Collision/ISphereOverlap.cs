using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// "Does a sphere at this centre with this radius overlap the geometry?" in the geometry's own space.
/// A centre or radius that is NaN or infinite, or a negative radius, never overlaps.
/// </summary>
internal interface ISphereOverlap
{
    bool Overlaps(Vector3 center, float radius);
}
