using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A part's tree asked through its <see cref="BspReachGrid"/>s: a query with one of their radii reads the voxel
/// and runs only what it leaves open; any other radius walks the tree (<see cref="BspSphereQuery"/>). The same
/// answers as the walk, bit for bit, either way.
/// </summary>
internal sealed class IndexedBspQuery(BspSphereQuery tree, IReadOnlyList<BspReachGrid> grids) : ISphereOverlap
{
    private readonly BspReachGrid[] _grids = [.. grids];

    public BspSphereQuery Tree { get; } = tree;

    public bool Overlaps(Vector3 center, float radius)
    {
        foreach (var grid in _grids)
            if (grid.Radius == radius) return grid.Overlaps(center);
        return Tree.Overlaps(center, radius);
    }
}
