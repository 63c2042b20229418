using System.Diagnostics;
using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// The <see cref="BspReachGrid"/>s one scene asks, for its mover radii: each tree's grid per part-local radius
/// built once (a GfxObj placed many times, or shared by many objects, is indexed once) and kept. Thread-safe.
/// </summary>
internal sealed class BspReachGrids(IReadOnlyList<float> moverRadii)
{
    private readonly float[] _moverRadii = [.. moverRadii.Distinct()];
    private readonly Dictionary<(CompiledBsp, float), BspReachGrid?> _grids = [];
    private readonly Lock _lock = new();
    private long _buildTicks;

    /// <summary>Bytes held by every grid built so far.</summary>
    public long Bytes
    {
        get { lock (_lock) return _grids.Values.Sum(g => g?.Bytes ?? 0); }
    }

    /// <summary>Time spent building the grids so far.</summary>
    public TimeSpan BuildTime => Stopwatch.GetElapsedTime(0, Interlocked.Read(ref _buildTicks));

    /// <summary>The tree of a part at <paramref name="pose"/>, asked through its grids for the mover radii in part units (<see cref="PartPose.ToLocal(Vector3, float)"/>).</summary>
    public IndexedBspQuery Index(BspSphereQuery tree, PartPose pose)
    {
        var grids = new List<BspReachGrid>();
        foreach (var r in _moverRadii)
            if (Grid(tree, pose.ToLocal(Vector3.Zero, r).Radius) is { } grid && !grids.Exists(g => g.Radius == grid.Radius)) grids.Add(grid);
        return new IndexedBspQuery(tree, grids);
    }

    /// <summary>The grid built for a tree and part-local radius, or null when none was.</summary>
    public BspReachGrid? Find(CompiledBsp bsp, float radius)
    {
        lock (_lock) return _grids.GetValueOrDefault((bsp, radius));
    }

    private BspReachGrid? Grid(BspSphereQuery tree, float radius)
    {
        lock (_lock)
        {
            if (_grids.TryGetValue((tree.Bsp, radius), out var known)) return known;
            var start = Stopwatch.GetTimestamp();
            var grid = BspReachGrid.Build(tree, radius);
            Interlocked.Add(ref _buildTicks, Stopwatch.GetTimestamp() - start);
            _grids[(tree.Bsp, radius)] = grid;
            return grid;
        }
    }
}
