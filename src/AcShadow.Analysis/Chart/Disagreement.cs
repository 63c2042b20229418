namespace AcShadow.Analysis.Chart;

/// <summary>
/// A probe where a model and the reference answer differently. FalsePass: the reference blocks, the model
/// lets the sphere through (walking through a closed door). Gaps: <see cref="BoundaryGap"/> to each
/// geometry; <see cref="Nearness"/> = the smaller of their magnitudes ranks "nearest the boundary".
/// </summary>
public sealed record Disagreement(int ProbeIndex, Probe Probe, bool FalsePass, float GapToReference, float GapToModel)
{
    public float Nearness => MathF.Min(MathF.Abs(GapToReference), MathF.Abs(GapToModel));
}
