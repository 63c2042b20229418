namespace AcShadow.Analysis.Chart.Output;

/// <summary>Colours: one per model in chart order (colour-blind-safe Okabe–Ito), and the failure-map verdicts.</summary>
internal static class ChartPalette
{
    private static readonly string[] Models = ["#000000", "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442"];

    public static string Model(int index) => Models[index % Models.Length];

    public const string AgreeBlocked = "#5a5a5a";
    public const string AgreeClear = "#ececec";
    public const string FalsePass = "#d62728";
    public const string FalseBlock = "#1f77b4";
    /// <summary>A movement verdict's colour: agreement grey, false pass red, false block blue, deflection orange, step mismatch purple, stand-off drift green.</summary>
    public static string Verdict(Movement.MovementVerdict verdict) => verdict switch
    {
        Movement.MovementVerdict.Agree => "#b0b0b0",
        Movement.MovementVerdict.FalsePass => FalsePass,
        Movement.MovementVerdict.FalseBlock => FalseBlock,
        Movement.MovementVerdict.Deflection => "#ff7f0e",
        Movement.MovementVerdict.StepMismatch => "#9467bd",
        _ => "#2ca02c",
    };

    public const string Axis = "#333333";
    public const string GridLine = "#dddddd";
}
