namespace AcShadow.Analysis.Audit;

/// <summary>
/// The shape family retail's CPhysicsObj::FindObjCollisions tests for a Setup: its parts' BSPs, its
/// CylSpheres, its Spheres, or nothing.
/// </summary>
public enum AuditCategory
{
    Bsp,
    Cylinders,
    Spheres,
    None,
}

public static class AuditCategories
{
    public static string Name(this AuditCategory c) => c switch
    {
        AuditCategory.Bsp => "bsp",
        AuditCategory.Cylinders => "cylinders",
        AuditCategory.Spheres => "spheres",
        _ => "none",
    };
}
