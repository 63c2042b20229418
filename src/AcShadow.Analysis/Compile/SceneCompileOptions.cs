using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Movement;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// How a scene is compiled: the probes (the chart's, stability probes for every mover radius in
/// <see cref="ChartOptions.Radii"/>), the entity scale, and the tolerance: a model qualifies when it never
/// lets a mover through where retail blocks and its false blocks are at most
/// <see cref="TolerancePercent"/> % of the object's probes (0: exact), and, with <see cref="Movement"/>, it never lets the
/// mover past where retail's walk stops.
/// </summary>
public sealed record SceneCompileOptions
{
    public ChartOptions Chart { get; init; } = new();
    public float EntityScale { get; init; } = 1f;
    public double TolerancePercent { get; init; }

    /// <summary>
    /// The mover and door catalog the objects' movement cases are walked with: a model is then chosen only when it
    /// also has no movement false pass (movement.md §4.2). Null: static probes only.
    /// </summary>
    public MovementChartOptions? Movement { get; init; }

    public string? Problem()
    {
        if (Chart.Problem() is { } problem) return problem;
        if (!double.IsFinite(TolerancePercent) || TolerancePercent < 0 || TolerancePercent > 100)
            return FormattableString.Invariant($"tolerance must be a percentage from 0 to 100, not {TolerancePercent}");
        return null;
    }

    /// <summary>Whether a model with these disagreements over this many probes may be chosen: never a false pass.</summary>
    public bool Accepts(int falsePass, int falseBlock, int probes) => falsePass == 0 && falseBlock * 100.0 <= TolerancePercent * probes;
}
