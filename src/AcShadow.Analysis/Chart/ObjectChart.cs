namespace AcShadow.Analysis.Chart;

/// <summary>
/// One object charted: its probes (grid, then doorway lines), the grid spacing used, the reference's
/// answers, each model's outcome in chart order, and the cheapest model (by median time) that agrees with
/// the reference on every probe; with <see cref="Movement"/>, the movement chart too.
/// </summary>
public sealed record ObjectChart(
    uint SetupId,
    IReadOnlyList<Probe> Probes,
    float GridSpacing,
    Bounds Bounds,
    DoorwayProbes.Opening? Doorway,
    bool[] Reference,
    IReadOnlyList<ModelOutcome> Models,
    string CheapestExact,
    IReadOnlyList<string> Notes)
{
    /// <summary>The object charted by movement too (`chart --movement`), else null.</summary>
    public Movement.ObjectMovementChart? Movement { get; init; }
}
