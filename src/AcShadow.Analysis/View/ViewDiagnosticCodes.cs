namespace AcShadow.Analysis.View;

/// <summary>What only view reports (its other warnings are the build's codes, e.g. <c>non-finite</c>).</summary>
public static class ViewDiagnosticCodes
{
    /// <summary>A shape reaches past <see cref="ViewSceneBuilder.MaxDistance"/> from the view's origin (a damaged coordinate such as 3.4e38): not drawn.</summary>
    public const string TooFarToDraw = "too-far-to-draw";
}
