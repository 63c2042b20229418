namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The factor a sphere (C, ρ) around an object's shapes must put on the mover's radius so that no mover it refuses
/// could be blocked: |c − C| ≤ ρ + r·stretch whenever a shape blocks (c, r). Spheres, boxes, hulls and trees block
/// only within r of themselves: 1. A CylSphere blocks a box in profile (CCylSphere::collides_with_sphere:
/// horizontal distance ≤ R − ε + r, |h/2 − dz| ≤ r − ε + h/2), every point of the cylinder moved by up to (r, r)
/// horizontally and vertically, so up to √2·r: √2, padded, when any shape is a cylinder.
/// </summary>
internal static class BoundStretch
{
    /// <summary>√2 and 1e-5 for the float rounding of the test and the bound (the cylinder's own ε is 0.0002 m).</summary>
    public static readonly float Cylinder = (float)(Math.Sqrt(2.0) * (1 + 1e-5));

    public static float Of(ISphereOverlap query) => HasCylinder(query) ? Cylinder : 1f;

    private static bool HasCylinder(ISphereOverlap query) => query switch
    {
        CylinderShapeQuery => true,
        ObjectOverlapQuery o => o.Parts.Any(HasCylinder),
        AnyOverlap a => a.Shapes.Any(HasCylinder),
        PosedQuery p => HasCylinder(p.PartQuery),
        _ => false,
    };
}
