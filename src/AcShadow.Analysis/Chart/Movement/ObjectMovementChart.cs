using System.Numerics;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// One object's movement chart: its movement cases (the reference's walks, as `acshadow move` writes them), every
/// model's walks over them in chart order (the reference first), each model's outline seen from above (for the
/// failure map) and the footprint the cases were laid out on, landblock-local.
/// </summary>
public sealed record ObjectMovementChart(
    uint SetupId,
    IReadOnlyList<MovementCase> Cases,
    IReadOnlyList<ModelMovement> Models,
    IReadOnlyList<ModelOutline> Outlines,
    Vector3 FootprintMin,
    Vector3 FootprintMax)
{
    /// <summary>The case <see cref="MovementChartOptions.Walk"/> names with each model's frames on it (model order), or null.</summary>
    public (int Case, IReadOnlyList<IReadOnlyList<MovementFrame>> Frames)? Walk { get; init; }

    /// <summary>Each case's fragility, in case order.</summary>
    public IReadOnlyList<bool> Fragile { get; } = [.. Cases.Select(c => c.Fragile)];

    /// <summary>The states the cases run in, in order of first use.</summary>
    public IReadOnlyList<string> States { get; } = [.. Cases.Select(c => c.State).Distinct()];
}
