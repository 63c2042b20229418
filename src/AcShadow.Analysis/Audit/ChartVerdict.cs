namespace AcShadow.Analysis.Audit;

/// <summary>
/// What the collision chart (<see cref="Chart.ChartRunner"/>) says about a Setup: the shape
/// models that agree with the retail reference on every probe (deterministic), and the cheapest of them
/// by measured median query time (timing-dependent: it can differ between runs when two exact models
/// cost about the same; null when none is exact).
/// </summary>
public sealed record ChartVerdict(IReadOnlyList<string> ExactModels, string? CheapestExact);
