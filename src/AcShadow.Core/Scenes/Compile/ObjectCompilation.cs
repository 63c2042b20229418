using AcShadow.Core.Chart;
using AcShadow.Core.Chart.Models;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Core.Scenes.Compile;

/// <summary>One model the compiler tried on an object, in ladder order, and whether it qualified.</summary>
public sealed record CandidateOutcome(string Model, int Shapes, int FalsePass, int FalseBlock, bool Accepted);

/// <summary>
/// One distinct object of a scene (a Setup or a bare GfxObj, every placement of it shares this) compiled:
/// the chosen model prepared, retail prepared, the probes and retail's answers, every candidate tried, and
/// the time per query of the chosen model and of retail over the probes. <see cref="Model"/> is null when
/// the object could not be described (see the diagnostics); "none" when nothing of it collides.
/// </summary>
public sealed record ObjectCompilation(
    uint Id,
    SceneObjectKind Kind,
    string? Model,
    PreparedModel? Chosen,
    PreparedModel? Retail,
    Probe[] Probes,
    bool[] RetailAnswers,
    bool[] ChosenAnswers,
    IReadOnlyList<CandidateOutcome> Candidates,
    TimingStats ChosenTiming,
    TimingStats RetailTiming,
    Bounds Bounds,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    public const string Nothing = "none";

    public int FalsePass => Candidates.Count == 0 ? 0 : Candidates[^1].FalsePass;
    public int FalseBlock => Candidates.Count == 0 ? 0 : Candidates[^1].FalseBlock;
    public bool NeedsBsp => Chosen is not null && Chosen.Shapes.Any(s => s.Bsp is not null);
}
