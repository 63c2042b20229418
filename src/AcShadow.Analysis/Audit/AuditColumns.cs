using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// The audit's columns, in output order; every format writes the report's columns. The chart columns
/// come only with `audit --chart` (the chart is slow and its "cheapest" is timing-dependent).
/// </summary>
public static class AuditColumns
{
    public static readonly IReadOnlyList<AuditColumn> All =
    [
        new("id", "Setup", r => JsonIds.Format(r.SetupId), "Setup id"),
        new("category", "Family", r => r.Category.Name(), "the shape family retail tests: bsp, cylinders, spheres or none"),
        new("parts", "Parts", r => r.Parts, "number of parts"),
        new("bspParts", "BSP parts", r => r.BspParts, "parts whose GfxObj has a PhysicsBSP"),
        new("missingParts", "Missing", r => r.MissingParts, "parts whose GfxObj is not in the dat or unreadable"),
        new("cylSpheres", "Cyls", r => r.CylSpheres, "CylSpheres"),
        new("spheres", "Spheres", r => r.Spheres, "Spheres"),
        new("radius", "Radius", r => r.Radius, "Setup.Radius"),
        new("height", "Height", r => r.Height, "Setup.Height"),
        new("flagBsp", "Flag BSP", r => r.FlagHasPhysicsBsp, "Setup.Flags HasPhysicsBSP (0x8)"),
        new("partsBsp", "Parts BSP", r => r.PartsHavePhysicsBsp, "a part has a PhysicsBSP (what retail computes)"),
        new("flagMismatch", "Mismatch", r => r.FlagMismatch, "the flag disagrees with the parts"),
        new("retailShapes", "Retail", r => r.RetailShapes, "shapes under --policy retail"),
        new("unionShapes", "Union", r => r.UnionShapes, "shapes under --policy union"),
        new("polygons", "Polygons", r => r.PhysicsPolygons, "physics polygons of the retail BSP shapes (per part, shared GfxObjs counted per part)"),
        new("placement", "Placement", r => r.Placement, "placement retail uses (Resting, Default or None)"),
        new("unionPlacement", "Union placement", r => r.UnionPlacement, "placement the union policy uses"),
        new("pose", "Pose", r => r.PoseSource, "what the retail pose comes from: placement, default-animation or motion-table"),
        new("motionTable", "Motion table", r => r.MotionTableId is { } m ? JsonIds.Format(m) : null, "the motion table the retail pose used"),
        new("poseDiffers", "Poses differ", r => r.PoseDiffers, "the retail pose moves a part more than 1 mm or 0.1 deg from the placement pose"),
        new("coverage", "Coverage", r => r.Coverage, "fraction of the BSP footprint inside the Radius circle (docs/batch.md)"),
        new("heightCoverage", "Height cov", r => r.HeightCoverage, "fraction of the BSP parts' height range inside [0, Setup.Height] (docs/batch.md)"),
        new("volumeCoverage", "Volume cov", r => r.VolumeCoverage, "coverage × height coverage: the fraction of the BSP parts' footprint prism the fallback cylinder fills (docs/batch.md)"),
        new("footprint", "Footprint m2", r => r.FootprintArea, "area of the BSP footprint, m²"),
        new("diagnostics", "Diagnostics", r => r.DiagnosticCodes, "diagnostic codes of the retail build"),
    ];

    public static readonly IReadOnlyList<AuditColumn> WithChart =
    [
        .. All,
        new("exactModels", "Exact models", r => r.Chart?.ExactModels, "chart models that agree with retail on every probe"),
        new("cheapestExact", "Cheapest exact", r => r.Chart?.CheapestExact, "the exact model with the lowest median query time (timing-dependent)"),
    ];

    public static AuditColumn? Find(string key) =>
        WithChart.FirstOrDefault(c => string.Equals(c.Key, key, StringComparison.OrdinalIgnoreCase));
}
