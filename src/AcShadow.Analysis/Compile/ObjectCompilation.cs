using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// One model the compiler tried on an object, in the order tried (fewest counted operations per query
/// first, <see cref="QueryCost"/>), and whether it qualified; <see cref="Movement"/>: its verdicts on the object's
/// movement cases (null when it was not walked: no movement asked, or its static probes already ruled it out).
/// </summary>
internal sealed record CandidateOutcome(string Model, int Shapes, int FalsePass, int FalseBlock, bool Accepted, double OpsPerQuery)
{
    public Chart.Movement.MovementCounts? Movement { get; init; }
}

/// <summary>
/// One distinct object of a scene (a Setup or a bare GfxObj, every placement of it shares this) compiled:
/// the chosen model prepared, retail prepared, the probes (compactly: what the whole-scene check and the reports read), every candidate tried, and
/// the time per query of the chosen model and of retail over the probes, and their counted cost. <see cref="Model"/> is null when
/// the object could not be described (see the diagnostics); "none" when nothing of it collides.
/// </summary>
internal sealed record ObjectCompilation(
    uint Id,
    SceneObjectKind Kind,
    string? Model,
    PreparedModel? Chosen,
    PreparedModel? Retail,
    ProbeSpheres Probes,
    IReadOnlyList<CandidateOutcome> Candidates,
    TimingStats ChosenTiming,
    TimingStats RetailTiming,
    Bounds Bounds,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    public const string Nothing = "none";

    /// <summary>
    /// What the tables and the summary show in the model column of an object or cell nothing was compiled for.
    /// A display label, not a diagnostic code: it reads like <c>ExportDiagnosticCodes.Unresolved</c>, the
    /// diagnostic that says why.
    /// </summary>
    public const string UnresolvedLabel = "unresolved";

    /// <summary>Counted operations per query (<see cref="QueryCost"/>) of the chosen model and of retail over the probes' sample.</summary>
    public double ChosenOps { get; init; }
    public double RetailOps { get; init; }

    public int FalsePass => Candidates.Count == 0 ? 0 : Candidates[^1].FalsePass;
    public int FalseBlock => Candidates.Count == 0 ? 0 : Candidates[^1].FalseBlock;
}
