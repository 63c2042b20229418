namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// The one set of colours every drawing acshadow writes uses (the chart's speed–accuracy plot and failure
/// maps, the scene chart, view's SVGs and glbs): each shape model has one colour wherever it appears
/// (colour-blind-safe Okabe–Ito hues, the reference a dark slate), and the failure maps' verdicts have theirs.
/// </summary>
public static class DrawingPalette
{
    /// <summary>The colour of a shape model (a chart model, a compiled scene's chosen model, or view's "cells"), "#RRGGBB"; grey for a name none has.</summary>
    public static string Model(string name) => name switch
    {
        "retail" => "#3B4452",
        "union" => "#CC79A7",
        "fallback-cylinder" => "#D55E00",
        "spheres" => "#009E73",
        "part-spheres" => "#56B4E9",
        "part-boxes" => "#0072B2",
        "part-hulls" => "#E69F00",
        "placement-pose" => "#B59F00",
        "cells" => "#A08560",
        _ => Unknown,
    };

    /// <summary>What a name no model has is drawn in (an unresolved object, a model this version does not know).</summary>
    public const string Unknown = "#8C8C8C";

    /// <summary>The whole compiled scene (the scene chart's bar), a colour no single model has.</summary>
    public const string Compiled = "#6A3D9A";

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
    public const string Ink = "#222222";
    public const string Note = "#555555";
    public const string Warning = "#B00020";
    public const string Panel = "#FBFBFB";
    public const string PanelEdge = "#BBBBBB";
}
