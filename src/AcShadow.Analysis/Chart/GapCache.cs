using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// One geometry's <see cref="BoundaryGap"/> per probe, measured the first time it is asked for: every model
/// that disagrees with the reference on a probe ranks it by the same reference gap, so it is measured once.
/// A bounded search that only proved the gap wider than some limit is remembered too, so the next model
/// asking with that limit or a tighter one is answered without searching again.
/// </summary>
internal sealed class GapCache(IReadOnlyList<PreparedShape> shapes, Probe[] probes)
{
    /// <summary>The geometry the gaps are measured to.</summary>
    public IReadOnlyList<PreparedShape> Shapes => shapes;

    private readonly float[] _gaps = new float[probes.Length];
    private readonly bool[] _known = new bool[probes.Length];

    // The widest limit the gap is proven wider than (either way); −∞ when nothing is proven.
    private readonly float[] _widerThan = Array.ConvertAll(probes, _ => float.NegativeInfinity);

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

    /// <summary>
    /// <see cref="BoundaryGap.Within"/> for one probe: the exact gap when it is known (then always
    /// <c>Known</c>), else certainly wider than <paramref name="limit"/> (<c>Known</c> false).
    /// </summary>
    public (float Gap, bool Known) Within(int probe, float limit)
    {
        if (_known[probe]) return (_gaps[probe], true);
        if (limit <= _widerThan[probe]) return (float.PositiveInfinity, false);
        var p = probes[probe];
        var (gap, known) = BoundaryGap.Within(shapes, p.Center, p.Radius, limit);
        if (known)
        {
            _gaps[probe] = gap;
            _known[probe] = true;
        }
        else _widerThan[probe] = limit;
        return (gap, known);
    }
}
