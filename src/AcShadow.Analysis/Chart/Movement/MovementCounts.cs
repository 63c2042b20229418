namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// One model's verdicts on one object's movement cases: how many cases, how many fragile, the count of each verdict
/// over the non-fragile cases (in <see cref="MovementVerdicts.All"/> order) and the false passes among the fragile ones.
/// </summary>
public sealed record MovementCounts(int Cases, int Fragile, IReadOnlyList<int> Verdicts, int FragileFalsePass)
{
    public int this[MovementVerdict verdict] => Verdicts[(int)verdict];

    /// <summary>Every false pass, fragile or not: a model with any is never trusted for movement.</summary>
    public int FalsePasses => this[MovementVerdict.FalsePass] + FragileFalsePass;
}
