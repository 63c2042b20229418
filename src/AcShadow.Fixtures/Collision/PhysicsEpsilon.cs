namespace AcShadow.Fixtures.Collision;

/// <summary>
/// Retail's collision tolerance (PhysicsGlobals EPSILON = 0.0002 m). Splitting-plane reach, polygon contact
/// and cylinder/sphere contact all shrink the query sphere by it, so a sphere only grazing a surface is clear.
/// </summary>
internal static class PhysicsEpsilon
{
    public const float Value = 0.0002f;
}
