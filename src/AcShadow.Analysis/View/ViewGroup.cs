namespace AcShadow.Analysis.View;

/// <summary>
/// What a viewer toggles as one layer: one shape model of every object (retail, union, the fallback
/// cylinder, the Setup's spheres), a compiled scene's objects of one chosen model, or one kind of chart
/// failure. <paramref name="Colour"/> is "#rrggbb".
/// </summary>
public sealed record ViewGroup(string Name, string Description, string Colour, IReadOnlyList<ViewObject> Objects)
{
    public int ShapeCount => Objects.Sum(o => o.Shapes.Count);

    /// <summary>
    /// Drawn filled, its objects numbered: the reference model when every object is shown under every model
    /// (the others are outlines over it); every model of a compiled scene, where each object is in one group.
    /// </summary>
    public bool Filled { get; init; }
}
