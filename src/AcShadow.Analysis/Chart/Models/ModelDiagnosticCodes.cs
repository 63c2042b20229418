namespace AcShadow.Analysis.Chart.Models;

/// <summary>The codes of the diagnostics a chart model adds when it prepares an object, stable for consumers that filter on them.</summary>
public static class ModelDiagnosticCodes
{
    /// <summary>A BSP part whose physics vertices give no solid for a fitted model (all on a line or in a point): that model leaves it out.</summary>
    /// <summary>A model threw while preparing an object: it answers "nothing collides" there, so every blocked probe is its false pass.</summary>
    public const string ModelFailed = "model-failed";

    public const string UnfittablePart = "unfittable-part";
}
