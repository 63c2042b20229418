namespace AcShadow.Analysis.Chart;

/// <summary>
/// The codes of the chart's own warnings (a model's diagnostics and the probe layout's notes), stable for
/// anyone who filters chart's stderr or its summary line's counts by code.
/// </summary>
public static class ChartDiagnosticCodes
{
    /// <summary>A model threw while preparing an object: it answers "nothing collides" there, so every blocked probe is its false pass.</summary>
    public const string ModelFailed = Models.ModelDiagnosticCodes.ModelFailed;
    /// <summary>The probe grid would pass <see cref="ChartOptions.MaxGridProbes"/>: its spacing was doubled until it fits.</summary>
    public const string GridCoarsened = "grid-coarsened";
    /// <summary>The stability probes would pass <see cref="ChartOptions.MaxStabilityProbes"/>: faces and edges were probed more coarsely.</summary>
    public const string StabilityCoarsened = "stability-coarsened";
}
