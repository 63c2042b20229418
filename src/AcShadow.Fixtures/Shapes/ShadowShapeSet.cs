namespace AcShadow.Fixtures.Shapes;

/// <summary>
/// Everything the builder decided for one Setup: the shapes, the placement frame, the pose the parts are
/// in (<see cref="Pose"/>), and what it could not resolve.
/// </summary>
public sealed record ShadowShapeSet(
    uint SetupId,
    ShapePolicy Policy,
    PlacementResolution Placement,
    float EntityScale,
    bool PartsHavePhysicsBsp,
    IReadOnlyList<ShadowShape> Shapes,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    public PoseProvenance Pose { get; init; } = PoseProvenance.Placement("placement");
}
