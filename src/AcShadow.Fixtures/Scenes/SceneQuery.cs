using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A landblock's objects asked together: a mover sphere (landblock-relative centre) is blocked when any
/// object blocks it. Each object is skipped by its bounding sphere first, as an engine's broad phase would.
/// Landblock-relative, not world, coordinates: float32 world coordinates lose millimetres at landblock
/// magnitudes, which is why the dat stores frames this way.
/// </summary>
public sealed class SceneQuery(IReadOnlyList<PlacedQuery> objects) : ISphereOverlap
{
    private readonly PlacedQuery[] _objects = [.. objects];

    public IReadOnlyList<PlacedQuery> Objects => _objects;

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius)) return false;
        foreach (var o in _objects)
            if (o.Overlaps(center, radius)) return true;
        return false;
    }

    /// <summary>The objects a sphere touches, by scene index.</summary>
    public IEnumerable<int> Touching(Vector3 center, float radius) =>
        _objects.Where(o => o.Overlaps(center, radius)).Select(o => o.Index);
}
