namespace AcShadow.Analysis.Chart;

/// <summary>
/// The codes of the chart's own warnings (the probe layout's notes; a model's are <see cref="Models.ModelDiagnosticCodes"/>), stable for
/// anyone who filters chart's stderr or its summary line's counts by code.
/// </summary>
public static class ChartDiagnosticCodes
{
    /// <summary>The probe grid would pass <see cref="ChartOptions.MaxGridProbes"/>: its spacing was doubled until it fits.</summary>
    public const string GridCoarsened = "grid-coarsened";
    /// <summary>The stability probes would pass <see cref="ChartOptions.MaxStabilityProbes"/>: faces and edges were probed more coarsely.</summary>
    public const string StabilityCoarsened = "stability-coarsened";
}
