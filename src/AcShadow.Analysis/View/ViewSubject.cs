using AcShadow.Core.Bsp;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.View;

/// <summary>
/// One shape model of an object: its name (a chart model's, e.g. "retail") and its shapes in the entity frame;
/// a fitted model (part spheres, boxes, hulls) has no shadow shapes and comes already drawn (<see cref="Drawn"/>).
/// </summary>
public sealed record ModelShapes(string Model, IReadOnlyList<ShadowShape> Shapes)
{
    public IReadOnlyList<ViewShape>? Drawn { get; init; }
}

/// <summary>
/// An object to view: its id, what it is ("Setup" or "GfxObj" for a bare GfxObj a landblock places), each
/// model's shapes, the BSP dumps its BSP shapes name, and what building its shapes reported.
/// </summary>
public sealed record ViewSubject(uint Id, string Kind, IReadOnlyList<ModelShapes> Models, Func<uint, BspDump?> Bsps)
{
    public IReadOnlyList<Diagnostic> Diagnostics { get; init; } = [];
}

/// <summary>A subject placed in a landblock: its scene index and its frame relative to the landblock's corner.</summary>
public sealed record ViewPlacement(int Index, ViewSubject Subject, Frame Frame);

/// <summary>An indoor cell of a landblock: its id, its landblock-relative frame and its physics polygons (the cell structure's dump).</summary>
public sealed record ViewCell(uint Id, Frame Frame, BspDump Physics);
