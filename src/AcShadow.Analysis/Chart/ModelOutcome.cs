using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart;

/// <summary>One model on one object: its answers, how they compare with the reference, its time per query.</summary>
public sealed record ModelOutcome(
    string Model,
    int ShapeCount,
    bool[] Answers,
    int Agree,
    int FalsePass,
    int FalseBlock,
    int DoorwayProbes,
    int DoorwayFalsePass,
    int DoorwayFalseBlock,
    TimingStats Timing,
    IReadOnlyList<Disagreement> Nearest,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    public int Probes => Answers.Length;
    public double AgreementPercent => Probes == 0 ? 100.0 : 100.0 * Agree / Probes;
    public bool Exact => FalsePass == 0 && FalseBlock == 0;
}
