using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// One Setup's audit: its parts and which carry a PhysicsBSP, its CylSpheres and Spheres, the
/// Radius×Height fallback, the HasPhysicsBSP flag against what the parts say, the shapes each policy
/// builds, the physics polygons retail tests, the placement used, and how much of the BSP footprint the
/// fallback cylinder covers (<see cref="FootprintCoverage"/>; null when there is no BSP footprint) and
/// how much of their height it spans (<see cref="Audit.HeightCoverage"/>). <see cref="Chart"/> is set only
/// when the audit ran the collision chart.
/// </summary>
public sealed record AuditRow(
    uint SetupId,
    int Parts,
    int BspParts,
    int MissingParts,
    int CylSpheres,
    int Spheres,
    float Radius,
    float Height,
    bool FlagHasPhysicsBsp,
    bool PartsHavePhysicsBsp,
    int RetailShapes,
    int UnionShapes,
    int PhysicsPolygons,
    string Placement,
    string UnionPlacement,
    double? Coverage,
    double? HeightCoverage,
    double? FootprintArea,
    AuditCategory Category,
    IReadOnlyList<string> DiagnosticCodes,
    ChartVerdict? Chart = null)
{
    public bool FlagMismatch => FlagHasPhysicsBsp != PartsHavePhysicsBsp;

    /// <summary>What the retail pose comes from: placement, default-animation or motion-table.</summary>
    public string PoseSource { get; init; } = Fixtures.Shapes.PoseProvenance.PlacementSource;

    /// <summary>The motion table the retail pose used, if any.</summary>
    public uint? MotionTableId { get; init; }

    /// <summary>The retail pose moves some part more than 1 mm or 0.1° from the placement pose.</summary>
    public bool PoseDiffers { get; init; }

    /// <summary>
    /// The fraction of the BSP parts' footprint prism (footprint × their height range) that the fallback
    /// cylinder fills: coverage × height coverage. A thin, tall door's 14 cm × 20 cm "soda can" scores
    /// about 0.01 here while its footprint coverage alone is about 0.1.
    /// </summary>
    public double? VolumeCoverage => Coverage is { } c && HeightCoverage is { } h
        ? Math.Round(c * h, 4, MidpointRounding.AwayFromZero)
        : null;
}
