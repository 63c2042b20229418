using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// Everything one view file shows: a name (the file stem, e.g. "0x020019FF"), a title line, the world
/// position of the view's origin (the landblock's corner for a landblock, zero for a Setup in its own frame;
/// the glb's root carries it in its extras, the geometry stays near the origin), the groups in a fixed
/// order, notes, and warnings ("0x02003000: non-uniform-scale: …": what building the objects reported and
/// what the view could not draw), which every drawing shows.
/// </summary>
public sealed record ViewScene(string Name, string Title, Vector3 WorldOrigin, IReadOnlyList<ViewGroup> Groups, IReadOnlyList<string> Notes)
{
    public IReadOnlyList<string> Warnings { get; init; } = [];
}
