using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// What asking the whole scene about one mover position costs, counted as <see cref="QueryCost"/> counts
/// an object (one unit a distance evaluation), along the walk <see cref="SceneQuery"/> takes: the sphere's
/// land cells found <see cref="LandCellReach"/>, their candidate list loaded <see cref="LandCellVisit"/>, then
/// for each object (or, the compiled scene, each part: <see cref="PlacedParts"/>) it holds its bounding sphere 1
/// and, for a position inside it, the turn into the object's frame and its model's count (each posed part's reach
/// in the entity frame 1 before its turn: <see cref="PartReach"/>); for each indoor cell registered there its root sphere in the
/// landblock 1 (<see cref="CellReach"/>) and, for a position inside it, the cell's turn and its tree's count;
/// stopping at the first that blocks; given the compiled scene's grids, a tree asked through its
/// voxel index counts as <see cref="QueryCost"/> counts an indexed tree. <see cref="SceneWalk.Exhaustive"/> counts the old walk
/// instead: every object's bounding sphere, then every cell; <see cref="SceneWalk.NarrowFloor"/> the narrow phase alone, the
/// floor no broad phase can go under. The count is a hand-made mirror of the query's path, so
/// each counted position is asked of the query too: a different answer means the mirror left the path, and it throws.
/// </summary>
internal static class SceneCost
{
    /// <summary>
    /// Finding the sphere's land cells: its cell and its offset in it (a division, a floor and a multiply an axis), then
    /// a compare a side for the plain range and, with stretched entries, one for the stretched range, and the clamps;
    /// about one distance evaluation.
    /// </summary>
    public const int LandCellReach = 1;

    /// <summary>Loading one candidate list: a mover range's flat array, or (a mover wider than a cell) one land cell's list.</summary>
    public const int LandCellVisit = 1;

    /// <summary>
    /// Counted ops per position along <paramref name="walk"/>; <paramref name="partsApart"/>: the compiled scene's walk, each
    /// posed part an entry of its own (<see cref="PlacedParts"/>); <paramref name="built"/>: the scene's query as it is
    /// asked (its partition, and its whole-scene grids, <see cref="SceneReachGrid"/>, counted along their path).
    /// </summary>
    public static double PerPosition(IReadOnlyList<PlacedObject> placed, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled,
        IReadOnlyList<CellCompilation> cells, Func<ObjectCompilation, PreparedModel?> pick, IReadOnlyList<Probe> positions, int sample,
        SceneWalk walk = SceneWalk.Partitioned, bool partsApart = false, BspReachGrids? grids = null, SceneQuery? built = null)
    {
        if (positions.Count == 0 || sample < 1) return 0;
        var entries = SceneCompiler.Entries(placed, compiled, pick, partsApart).ToArray();
        var objects = entries.Select(e =>
        {
            IReadOnlyList<PreparedShape> shapes = e.Entry.Shapes is { } asked ? [.. asked.Select(i => e.Model.Shapes[i])] : e.Model.Shapes;
            // A part registered apart is asked behind its reach already (its landblock bound), not again.
            return new ObjectCounter(e.Entry, new QueryCost.Counter(shapes, partReach: e.Entry.Shapes is null, grids));
        }).ToArray();
        var cellCounters = cells.Where(c => c.Bsp is not null)
            .Select(c => (c.Frame, Counter: new QueryCost.Counter([new PreparedShape(CellShape, "cell", new PartPose(Vector3.Zero, Quaternion.Identity, 1f), c.Bsp)], grids: grids))).ToArray();
        // The scene's own query when the caller has built it (the same entries in the same order), else one for the count.
        var query = built ?? new SceneQuery([.. entries.Select(e => e.Entry)], SceneCompiler.CellQueries(cells));
        if (query.Objects.Count != entries.Length) throw new ArgumentException($"{query.Objects.Count} entries in the query, {entries.Length} counted", nameof(built));
        var partition = query.Partition;
        CellReach[] cellReach = [.. query.CellReaches];
        var n = Math.Min(sample, positions.Count);
        var asked = walk == SceneWalk.Partitioned ? query : query.Exhaustive;
        long total = 0;
        for (var i = 0; i < n; i++)
        {
            var p = positions[(int)((long)i * positions.Count / n)];
            var (ops, blocked) = walk switch
            {
                SceneWalk.Exhaustive => CountAll(p.Center, p.Radius),
                SceneWalk.NarrowFloor => CountNarrowFloor(p.Center, p.Radius),
                _ => CountPartitioned(p.Center, p.Radius),
            };
            // The counted walk mirrors the query's path by hand: where it reaches another answer, it took another path.
            if (blocked != asked.Overlaps(p.Center, p.Radius))
                throw new InvalidOperationException($"the counted {walk} walk answered {(blocked ? "blocked" : "clear")} at {p.Center} r {p.Radius} where the scene's query did not: SceneCost no longer follows the query's path");
            total += ops;
        }
        return (double)total / n;

        (long Ops, bool Blocked) CountPartitioned(Vector3 center, float radius)
        {
            if (!SphereBounds.IsValidProbe(center, radius)) return (0, false);
            foreach (var grid in query.Grids)
                if (grid.Radius == radius) return CountGrid(grid, center, radius);
            var counting = new Counting(objects, cellCounters, cellReach, center, radius) { Ops = LandCellReach };
            var blocked = partition.Any(center, radius, ref counting);
            return (counting.Ops, blocked);
        }

        // The whole-scene grid's path: the voxel lookup 1, then each open entry's broad phases (its object's sphere and
        // its own bound) when the voxel leaves them open, the turns (the object's once per object, then the part's or
        // the cell's) and its tree's frontier as the walk counts it; an entry asked whole counts its model (or the
        // cell's tree) from the turn on, as the grid asks it.
        (long Ops, bool Blocked) CountGrid(SceneReachGrid grid, Vector3 center, float radius)
        {
            var counting = new Counting(objects, cellCounters, cellReach, center, radius) { Ops = GridLookup };
            foreach (var e in grid.Always)
                if (counting.Test(e)) return (counting.Ops, true);
            var (_, voxelBlocked, items) = grid.At(center);
            if (voxelBlocked) return (counting.Ops, true);
            object? frame = null;
            foreach (var (entry, gated, program, guarded) in items)
            {
                if (entry >= objects.Length)
                {
                    var c = entry - objects.Length;
                    if (gated && !cellReach[c].Reaches(center, radius)) { counting.Ops++; continue; }
                    counting.Ops += gated ? 1 : 0;
                    bool cellBlocked;
                    if (program is null)
                    {
                        // Asked whole: the cell's turn, then its tree's count.
                        var (cellFrame, counter) = cellCounters[c];
                        var (cellLocal, cellRadius) = cellFrame.ToLocal(center, radius);
                        counting.Ops += counter.Count(cellLocal, cellRadius, out cellBlocked);
                    }
                    else
                    {
                        var cell = query.Cells[c].Query;
                        counting.Ops += QueryCost.Transform + QueryCost.Frontier(cell.Tree.Bsp, program, guarded, cell.ToCell(center), radius, out cellBlocked);
                    }
                    if (cellBlocked) return (counting.Ops, true);
                    continue;
                }
                var (placed, model) = objects[entry];
                if (gated)
                {
                    counting.Ops += placed.Whole is null ? 1 : 2;
                    if (placed.Whole is { } whole && !whole.Near(center, radius) || !placed.Near(center, radius)) continue;
                }
                if (!ReferenceEquals(frame, placed.FrameKey)) counting.Ops += QueryCost.Transform;
                frame = placed.FrameKey;
                var (local, r) = placed.ToEntity(center, radius);
                bool blocked;
                if (program is null)
                    // Asked whole from the turn on: the model's own count.
                    counting.Ops += model.Count(local, r, out blocked);
                else
                {
                    var posed = (PosedQuery)placed.EntityQuery;
                    var (partLocal, partRadius) = posed.Pose.ToLocal(local, r);
                    counting.Ops += QueryCost.Transform + QueryCost.Frontier(PosedTree(posed).Bsp, program, guarded, partLocal, partRadius, out blocked);
                }
                if (blocked) return (counting.Ops, true);
            }
            return (counting.Ops, false);
        }

        // Every entry's narrow phase where the sphere is within its own bound (the bound test itself free): a clear position
        // pays them all, a blocked one only its cheapest blocker, whatever order a walk might find it in.
        (long Ops, bool Blocked) CountNarrowFloor(Vector3 center, float radius)
        {
            if (!SphereBounds.IsValidProbe(center, radius)) return (0, false);
            long all = 0, cheapestBlocker = long.MaxValue;
            for (var e = 0; e < objects.Length + cellCounters.Length; e++)
            {
                long ops;
                bool blocked;
                if (e >= objects.Length)
                {
                    var c = e - objects.Length;
                    if (!cellReach[c].Reaches(center, radius)) continue;
                    var (cellFrame, counter) = cellCounters[c];
                    var (cellLocal, cellRadius) = cellFrame.ToLocal(center, radius);
                    ops = counter.Count(cellLocal, cellRadius, out blocked);
                }
                else
                {
                    var (o, model) = objects[e];
                    if (!o.Near(center, radius)) continue;
                    var (local, r) = o.Frame.ToLocal(center, radius);
                    ops = QueryCost.Transform + model.Count(local, r, out blocked);
                }
                all += ops;
                if (blocked) cheapestBlocker = Math.Min(cheapestBlocker, ops);
            }
            return cheapestBlocker == long.MaxValue ? (all, false) : (cheapestBlocker, true);
        }

        (long Ops, bool Blocked) CountAll(Vector3 center, float radius)
        {
            if (!SphereBounds.IsValidProbe(center, radius)) return (0, false);
            var counting = new Counting(objects, cellCounters, null, center, radius);
            for (var e = 0; e < objects.Length + cellCounters.Length; e++)
                if (counting.Test(e)) return (counting.Ops, true);
            return (counting.Ops, false);
        }
    }

    /// <summary>
    /// Finding a centre's voxel in the whole-scene grid: a few multiplies and an octree descent whose reads depend on
    /// one another, in a grid of megabytes. Weighed by the clock, not by its float operations (which made it 1): a
    /// position whose voxel is Clear or Blocked costs only this, 14-23 ns on the scale dat's 0x0000 and the sample, where
    /// all-retail's counted unit costs 3.7-3.8 ns over all the timed positions (docs/performance.md, eighth session).
    /// </summary>
    public const int GridLookup = 4;

    private static BspSphereQuery PosedTree(PosedQuery posed) => posed.PartQuery switch
    {
        IndexedBspQuery indexed => indexed.Tree,
        _ => (BspSphereQuery)posed.PartQuery,
    };

    /// <summary>An entry and its model's counter; its sphere tests are the entry's own (<see cref="PlacedQuery.Near"/>, the mover's radius stretched as the query stretches it).</summary>
    private sealed record ObjectCounter(PlacedQuery Entry, QueryCost.Counter Counter);

    /// <summary>One position's count along a walk (<paramref name="cellReach"/> null: the exhaustive walk, which turns into every cell).</summary>
    private struct Counting(ObjectCounter[] objects, (PartPose Frame, QueryCost.Counter Counter)[] cells, CellReach[]? cellReach, Vector3 center, float radius) : LandCellPartition.IEntryTest
    {
        public long Ops;
        /// <summary>The frame of the last entry: the parts of one object share its whole sphere's test (0 not asked, 1 met, 2 missed) and the turn, as the query does.</summary>
        private object? _frame;
        private int _whole;
        private bool _turned;

        public bool Test(int entry)
        {
            if (entry >= objects.Length)
            {
                var cell = entry - objects.Length;
                if (cellReach is not null)
                {
                    Ops++;
                    if (!cellReach[cell].Reaches(center, radius)) return false;
                }
                var (frame, counter) = cells[cell];
                var (cellLocal, cellRadius) = frame.ToLocal(center, radius);
                // The cell's own turn, then the tree's count (which counts a part's turn of its own, at identity here).
                Ops += counter.Count(cellLocal, cellRadius, out var cellBlocked);
                return cellBlocked;
            }
            var (o, model) = objects[entry];
            if (!ReferenceEquals(o.FrameKey, _frame)) (_frame, _whole, _turned) = (o.FrameKey, 0, false);
            if (o.Whole is { } whole)
            {
                if (_whole == 0)
                {
                    Ops++;
                    _whole = whole.Near(center, radius) ? 1 : 2;
                }
                if (_whole == 2) return false;
            }
            Ops++;
            if (!o.Near(center, radius)) return false;
            var (local, r) = o.Frame.ToLocal(center, radius);
            if (!_turned) Ops += QueryCost.Transform;
            _turned = true;
            Ops += model.Count(local, r, out var blocked);
            return blocked;
        }

        public void Visit() => Ops += LandCellVisit;
    }

    private static readonly Fixtures.Shapes.ShadowShape CellShape = new(Fixtures.Shapes.ShapeSource.Part, 0, null, Fixtures.Shapes.CollisionType.Bsp,
        Vector3.Zero, Quaternion.Identity, 1f, 0f, 0f, null);
}
