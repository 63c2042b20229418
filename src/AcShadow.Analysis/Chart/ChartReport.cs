namespace AcShadow.Analysis.Chart;

/// <summary>Everything a chart run produced: the options, the models in order (the first is the reference), one chart per object.</summary>
public sealed record ChartReport(ChartOptions Options, IReadOnlyList<string> Models, IReadOnlyList<ObjectChart> Objects)
{
    public string Reference => Models[0];
}
