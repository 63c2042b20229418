namespace AcShadow.Core.View;

/// <summary>
/// What a viewer toggles as one layer: one shape model of every object (retail, union, the fallback
/// cylinder, the Setup's spheres), or one kind of chart failure. <paramref name="Colour"/> is "#rrggbb".
/// </summary>
public sealed record ViewGroup(string Name, string Description, string Colour, IReadOnlyList<ViewObject> Objects)
{
    public int ShapeCount => Objects.Sum(o => o.Shapes.Count);
}
