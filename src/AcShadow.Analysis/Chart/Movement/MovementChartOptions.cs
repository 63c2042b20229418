using AcShadow.Fixtures.Movement;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// What the movement chart walks: the mover (a Setup's spheres and step heights) and which objects are doors
/// (walked through their gate, closed and open; any other object is walked at from 16 directions).
/// </summary>
public sealed record MovementChartOptions(Mover Mover, Func<uint, bool> IsDoor)
{
    /// <summary>A case id whose walk is kept frame by frame for every model (the walk drawings), or null.</summary>
    public string? Walk { get; init; }
}
