namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// One model's movement verdicts over every object of a run (<see cref="MovementTally"/>): the cases, the count
/// of each verdict on non-fragile cases (in <see cref="MovementVerdicts.All"/> order), the fragile cases and
/// their false passes, the objects it false-passed on, and the time per transition pooled over every walk.
/// </summary>
public sealed record MovementSummary(string Model, int Objects, long Cases, IReadOnlyList<long> Counts, long FragileCases,
    long FragileFalsePass, int FalsePassObjects, long Transitions, double NsPerTransition)
{
    /// <summary>Non-fragile cases judged <see cref="MovementVerdict.Agree"/>, per cent of the non-fragile cases.</summary>
    public double AgreementPercent => Cases - FragileCases == 0 ? 100.0 : 100.0 * Counts[(int)MovementVerdict.Agree] / (Cases - FragileCases);
}
