namespace AcShadow.Fixtures.Shapes;

/// <summary>Everything the builder decided for one Setup: the shapes, the placement used, and what it could not resolve.</summary>
public sealed record ShadowShapeSet(
    uint SetupId,
    ShapePolicy Policy,
    PlacementResolution Placement,
    float EntityScale,
    bool PartsHavePhysicsBsp,
    IReadOnlyList<ShadowShape> Shapes,
    IReadOnlyList<Diagnostic> Diagnostics);
