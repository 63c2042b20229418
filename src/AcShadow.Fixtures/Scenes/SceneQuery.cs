using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A landblock's objects and indoor cells asked together: a mover sphere (landblock-relative centre) is
/// blocked when any object or cell blocks it. Each object is skipped by its bounding sphere first, as an
/// engine's broad phase would; a cell by its tree's root sphere, as retail does.
/// Landblock-relative, not world, coordinates: float32 world coordinates lose millimetres at landblock
/// magnitudes, which is why the dat stores frames this way.
/// </summary>
internal sealed class SceneQuery(IReadOnlyList<PlacedQuery> objects, IReadOnlyList<SceneCell>? cells = null) : ISphereOverlap
{
    private readonly PlacedQuery[] _objects = [.. objects];
    private readonly SceneCell[] _cells = [.. cells ?? []];

    public IReadOnlyList<PlacedQuery> Objects => _objects;

    public IReadOnlyList<SceneCell> Cells => _cells;

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius)) return false;
        foreach (var o in _objects)
            if (o.Overlaps(center, radius)) return true;
        foreach (var c in _cells)
            if (c.Query.Overlaps(center, radius)) return true;
        return false;
    }

    /// <summary>The cells whose walls, floors or ceilings a sphere touches.</summary>
    public IEnumerable<uint> TouchingCells(Vector3 center, float radius) =>
        _cells.Where(c => c.Query.Overlaps(center, radius)).Select(c => c.CellId);
}
