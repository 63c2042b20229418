using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Shapes;

/// <summary>Which rule set turns a Setup into collision shapes.</summary>
public enum ShapePolicy
{
    /// <summary>
    /// Retail (CPhysicsObj::FindObjCollisions): parts' PhysicsBSPs if any part has one, else CylSpheres,
    /// else Spheres. Placement Resting → Default → none; part scale from DefaultScale.
    /// </summary>
    Retail,

    /// <summary>
    /// The seed design's ShadowShapeBuilder: every CylSphere, every Sphere when there are no
    /// CylSpheres (as a cylinder of height 2r), every part with a PhysicsBSP; placement Resting →
    /// Default → first available; no DefaultScale.
    /// </summary>
    Union,
}

internal static class ShapePolicies
{
    public static string Name(this ShapePolicy policy) => policy switch
    {
        ShapePolicy.Retail => "retail",
        ShapePolicy.Union => "union",
        _ => throw new ArgumentOutOfRangeException(nameof(policy)),
    };

    public static bool TryParse(string text, out ShapePolicy policy)
    {
        switch (text.ToLowerInvariant())
        {
            case "retail": policy = ShapePolicy.Retail; return true;
            case "union": policy = ShapePolicy.Union; return true;
            default: policy = default; return false;
        }
    }
}
