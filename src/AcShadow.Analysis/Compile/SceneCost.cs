using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// What asking the whole scene about one mover position costs, counted as <see cref="QueryCost"/> counts
/// an object (one unit a distance evaluation): each placed object's bounding sphere 1, and for a position
/// inside it the turn into the object's frame and its model's count; then each cell's turn into its frame
/// and its tree's count; stopping at the first that blocks, as <see cref="SceneQuery"/> does.
/// </summary>
internal static class SceneCost
{
    public static double PerPosition(IReadOnlyList<PlacedObject> placed, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled,
        IReadOnlyList<CellCompilation> cells, Func<ObjectCompilation, PreparedModel?> pick, IReadOnlyList<Probe> positions, int sample)
    {
        if (positions.Count == 0 || sample < 1) return 0;
        var objects = SceneCompiler.Placements(placed, compiled, pick).Select(o =>
        {
            var frame = new PartPose(o.Placed.Object.Frame.Position, ClientFrameMatrix.PlacedRotation(o.Placed.Object.Frame.Rotation), 1f);
            return (Frame: frame, Bound: frame.ToEntity(o.Center), o.Radius, Counter: new QueryCost.Counter(o.Model.Shapes));
        }).ToArray();
        var cellCounters = cells.Where(c => c.Bsp is not null)
            .Select(c => (c.Frame, Counter: new QueryCost.Counter([new PreparedShape(CellShape, "cell", new PartPose(Vector3.Zero, Quaternion.Identity, 1f), c.Bsp)]))).ToArray();
        var n = Math.Min(sample, positions.Count);
        long total = 0;
        for (var i = 0; i < n; i++)
        {
            var p = positions[(int)((long)i * positions.Count / n)];
            total += Count(p.Center, p.Radius);
        }
        return (double)total / n;

        long Count(Vector3 center, float radius)
        {
            long ops = 0;
            foreach (var o in objects)
            {
                ops++;
                float dx = center.X - o.Bound.X, dy = center.Y - o.Bound.Y, dz = center.Z - o.Bound.Z, sum = o.Radius + radius;
                if (!(dx * dx + dy * dy + dz * dz <= sum * sum)) continue;
                var (local, r) = o.Frame.ToLocal(center, radius);
                ops += QueryCost.Transform + o.Counter.Count(local, r, out var blocked);
                if (blocked) return ops;
            }
            foreach (var (frame, counter) in cellCounters)
            {
                var (local, r) = frame.ToLocal(center, radius);
                // The cell's own turn, then the tree's count (which counts a part's turn of its own, at identity here).
                ops += counter.Count(local, r, out var blocked);
                if (blocked) return ops;
            }
            return ops;
        }
    }

    private static readonly Fixtures.Shapes.ShadowShape CellShape = new(Fixtures.Shapes.ShapeSource.Part, 0, null, Fixtures.Shapes.CollisionType.Bsp,
        Vector3.Zero, Quaternion.Identity, 1f, 0f, 0f, null);
}
