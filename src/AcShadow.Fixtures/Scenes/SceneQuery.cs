using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// A landblock's objects and indoor cells asked together: a mover sphere (landblock-relative centre) is
/// blocked when any object or cell blocks it. As the client does, the sphere is asked only of what is
/// registered in the land cells it reaches (<see cref="LandCellPartition"/>: calc_cross_cells for the
/// objects, find_cell_list for the mover); each object is then skipped by its bounding sphere first, as an
/// engine's broad phase would, and a cell by its tree's root sphere, as retail does.
/// <see cref="Exhaustive"/> asks every object and every cell instead: the same answers, bit for bit (the
/// partition skips only what cannot block), kept as the oracle and the benchmark's baseline.
/// Landblock-relative, not world, coordinates: float32 world coordinates lose millimetres at landblock
/// magnitudes, which is why the dat stores frames this way.
/// </summary>
internal sealed class SceneQuery : ISphereOverlap
{
    private readonly PlacedQuery[] _objects;
    private readonly SceneCell[] _cells;
    private readonly CellReach[] _cellReach;
    private readonly SceneReachGrid[] _grids;

    /// <param name="objects">The placed objects (or parts), in scene order.</param>
    /// <param name="cells">The indoor cells.</param>
    /// <param name="gridRadii">Mover radii to decide the whole scene for ahead of time (<see cref="SceneReachGrid"/>): the compiled scene's.</param>
    public SceneQuery(IReadOnlyList<PlacedQuery> objects, IReadOnlyList<SceneCell>? cells = null, IReadOnlyList<float>? gridRadii = null)
    {
        _objects = [.. objects];
        _cells = [.. cells ?? []];
        _cellReach = [.. _cells.Select(c => CellReach.Of(c.Query.Bound))];
        // Each object by the sphere its own broad phase reaches, with its own stretch: a cylinder's wider reach costs
        // only the movers near it, not every query.
        Partition = LandCellPartition.Build([.. _objects.Select(o => ((Vector3, float)?)o.LandblockReach), .. _cells.Select(c => c.Query.Bound)],
            [.. _objects.Select(o => o.RadiusStretch), .. _cells.Select(_ => 1f)]);
        Exhaustive = new ExhaustiveWalk(_objects, _cells);
        _grids = [.. (gridRadii ?? []).Distinct().Select(r => SceneReachGrid.Build(_objects, _cells, _cellReach, r)).OfType<SceneReachGrid>()];
    }

    /// <summary>The whole-scene grids, one per mover radius asked for.</summary>
    public IReadOnlyList<SceneReachGrid> Grids => _grids;

    public IReadOnlyList<PlacedQuery> Objects => _objects;

    public IReadOnlyList<SceneCell> Cells => _cells;

    /// <summary>Each cell's broad phase in the landblock's frame, in <see cref="Cells"/> order.</summary>
    public IReadOnlyList<CellReach> CellReaches => _cellReach;

    /// <summary>The land cells the objects (entries 0..n-1) and then the cells (entries n..) are registered in.</summary>
    public LandCellPartition Partition { get; }

    /// <summary>The same question asked of every object and every cell, in order: the walk the partition (and every grid) must agree with.</summary>
    public ISphereOverlap Exhaustive { get; }

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius)) return false;
        foreach (var grid in _grids)
            if (grid.Radius == radius) return grid.Overlaps(center);
        var test = new EntryTest(_objects, _cells, _cellReach, center, radius);
        return Partition.Any(center, radius, ref test);
    }

    /// <summary>The cells whose walls, floors or ceilings a sphere touches, in scene order.</summary>
    public IEnumerable<uint> TouchingCells(Vector3 center, float radius) =>
        _cells.Where((c, i) => Partition.Reaches(_objects.Length + i, center, radius) && c.Query.Overlaps(center, radius)).Select(c => c.CellId);

    private struct EntryTest(PlacedQuery[] objects, SceneCell[] cells, CellReach[] cellReach, Vector3 center, float radius) : LandCellPartition.IEntryTest
    {
        /// <summary>
        /// The frame of the last entry asked, whether its whole object's sphere was met (0 not asked, 1 met, 2 missed),
        /// and the sphere turned into it once (an object's parts share the test and the turn: the same float operations).
        /// </summary>
        private object? _frame;
        private int _whole;
        private bool _turned;
        private Vector3 _local;
        private float _localRadius;

        public bool Test(int entry)
        {
            if (entry < objects.Length)
            {
                var o = objects[entry];
                if (!ReferenceEquals(o.FrameKey, _frame)) (_frame, _whole, _turned) = (o.FrameKey, 0, false);
                if (o.Whole is { } whole)
                {
                    if (_whole == 0) _whole = whole.Near(center, radius) ? 1 : 2;
                    if (_whole == 2) return false;
                }
                if (!o.Near(center, radius)) return false;
                if (!_turned)
                {
                    (_local, _localRadius) = o.ToEntity(center, radius);
                    _turned = true;
                }
                return o.EntityQuery.Overlaps(_local, _localRadius);
            }
            var cell = entry - objects.Length;
            return cellReach[cell].Reaches(center, radius) && cells[cell].Query.Overlaps(center, radius);
        }

        public readonly void Visit() { }
    }

    private sealed class ExhaustiveWalk(PlacedQuery[] objects, SceneCell[] cells) : ISphereOverlap
    {
        public bool Overlaps(Vector3 center, float radius)
        {
            if (!SphereBounds.IsValidProbe(center, radius)) return false;
            foreach (var o in objects)
                if (o.Overlaps(center, radius)) return true;
            foreach (var c in cells)
                if (c.Query.Overlaps(center, radius)) return true;
            return false;
        }
    }
}
