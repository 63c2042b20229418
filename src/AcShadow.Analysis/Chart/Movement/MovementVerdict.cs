namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// What a candidate model's walk came to against the reference's on the same case (movement.md §4.2), first
/// match in this order after <see cref="Agree"/>: a false pass is never tolerated.
/// </summary>
public enum MovementVerdict
{
    Agree,
    FalsePass,
    FalseBlock,
    Deflection,
    StepMismatch,
    StandOffDrift,
}

public static class MovementVerdicts
{
    /// <summary>Every verdict, in order.</summary>
    public static readonly MovementVerdict[] All = Enum.GetValues<MovementVerdict>();

    /// <summary>The verdict's name in CSV headers and SVG legends.</summary>
    public static string Name(MovementVerdict verdict) => verdict switch
    {
        MovementVerdict.Agree => "agree",
        MovementVerdict.FalsePass => "false_pass",
        MovementVerdict.FalseBlock => "false_block",
        MovementVerdict.Deflection => "deflection",
        MovementVerdict.StepMismatch => "step_mismatch",
        _ => "standoff_drift",
    };
}
