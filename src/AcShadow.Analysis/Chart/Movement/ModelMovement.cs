using System.Numerics;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// One model's walks over one object's movement cases, case by case in the object's case order: its verdict
/// against the reference, where it ended and the first frame it parted from the reference (null: never), with
/// the shapes it ran as and the time it took per transition (a measurement: it varies run to run).
/// </summary>
public sealed record ModelMovement(
    string Model,
    int Shapes,
    IReadOnlyList<MovementVerdict> Verdicts,
    IReadOnlyList<Vector3> Ends,
    IReadOnlyList<int?> FirstDivergingFrames,
    long Transitions,
    double NsPerTransition)
{
    /// <summary>How many non-fragile cases got <paramref name="verdict"/>; fragile cases are counted apart (<see cref="FragileCount"/>).</summary>
    public int Count(MovementVerdict verdict, IReadOnlyList<bool> fragile) =>
        Verdicts.Where((v, i) => v == verdict && !fragile[i]).Count();

    /// <summary>How many fragile cases got <paramref name="verdict"/>.</summary>
    public int FragileCount(MovementVerdict verdict, IReadOnlyList<bool> fragile) =>
        Verdicts.Where((v, i) => v == verdict && fragile[i]).Count();

    /// <summary>The verdict counts over these cases (fragile ones apart), as the compiled scene's evidence lists them.</summary>
    public MovementCounts Counts(IReadOnlyList<bool> fragile) =>
        new(Verdicts.Count, fragile.Count(f => f), [.. MovementVerdicts.All.Select(v => Count(v, fragile))], FragileCount(MovementVerdict.FalsePass, fragile));

    /// <summary>False passes, fragile or not: the count a model must keep at zero to be trusted for movement.</summary>
    public int FalsePasses => Verdicts.Count(v => v == MovementVerdict.FalsePass);
}
