namespace AcShadow.Analysis.View;

/// <summary>
/// What a viewer toggles as one layer: one shape model of every object (retail, union, the fallback
/// cylinder, the Setup's spheres), a compiled scene's objects of one chosen model, or one model's chart
/// failures of one verdict. <paramref name="Name"/> is its id (a model's name, "part-boxes false passes");
/// <paramref name="Colour"/> is "#RRGGBB" from <see cref="Chart.Output.DrawingPalette"/>.
/// </summary>
public sealed record ViewGroup(string Name, string Description, string Colour, IReadOnlyList<ViewObject> Objects)
{
    public int ShapeCount => Objects.Sum(o => o.Shapes.Count);

    /// <summary>
    /// The reference: drawn first, filled and opaque, its objects numbered. In a Setup or landblock view the
    /// reference model (retail, or a shadow file's own policy); in a compiled scene every chosen model, where
    /// each object is in one group and nothing overlays anything. Every other layer is an outline in the SVG
    /// and translucent in the glb, so the reference always shows through it.
    /// </summary>
    public bool Filled { get; init; }

    /// <summary>What the name alone does not say, shown after it in legends and node names: "3 shapes the same as retail's, not repeated".</summary>
    public string? Note { get; init; }

    /// <summary>Set on a chart-failure layer: which verdict its markers mark (false pass or false block).</summary>
    public bool? FalsePass { get; init; }

    /// <summary>The layer's name as legends and viewers show it: the name, and the note when there is one.</summary>
    public string Title => Note is null ? Name : $"{Name} ({Note})";
}
