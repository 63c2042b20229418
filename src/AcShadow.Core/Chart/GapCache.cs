using AcShadow.Fixtures.Collision;

namespace AcShadow.Core.Chart;

/// <summary>
/// One geometry's <see cref="BoundaryGap"/> per probe, measured the first time it is asked for: every model
/// that disagrees with the reference on a probe ranks it by the same reference gap, so it is measured once.
/// </summary>
internal sealed class GapCache(IReadOnlyList<PreparedShape> shapes, Probe[] probes)
{
    /// <summary>The geometry the gaps are measured to.</summary>
    public IReadOnlyList<PreparedShape> Shapes => shapes;

    private readonly float[] _gaps = new float[probes.Length];
    private readonly bool[] _known = new bool[probes.Length];

    public float this[int probe]
    {
        get
        {
            if (_known[probe]) return _gaps[probe];
            var p = probes[probe];
            _gaps[probe] = BoundaryGap.Of(shapes, p.Center, p.Radius);
            _known[probe] = true;
            return _gaps[probe];
        }
    }
}
