using System.Collections;
using System.Numerics;
using AcShadow.Analysis.Chart;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// A compiled object's or cell's probes as the scene keeps them until it is written: each probe's centre,
/// kind and radius, the radius as an index into the few distinct radii (the probe radius and the mover
/// radii), 14 bytes a probe against a <see cref="Probe"/>'s 28. The whole-scene check reads only centre and
/// radius, the reports only the kinds; a doorway probe's line and offset are not kept (read back, they are
/// the defaults). On the scale dat's busy landblock (8.8 million probes) this is 123 MB instead of 246 MB.
/// </summary>
internal sealed class ProbeSpheres : IReadOnlyList<Probe>
{
    private readonly Vector3[] _centers;
    private readonly byte[] _kinds;
    private readonly byte[] _radiusIndex;
    private readonly float[] _radii;

    public static ProbeSpheres Empty { get; } = new([]);

    public ProbeSpheres(IReadOnlyList<Probe> probes)
    {
        _centers = new Vector3[probes.Count];
        _kinds = new byte[probes.Count];
        _radiusIndex = new byte[probes.Count];
        var radii = new List<float>();
        for (var i = 0; i < probes.Count; i++)
        {
            var p = probes[i];
            _centers[i] = p.Center;
            _kinds[i] = checked((byte)p.Kind);
            // By bit pattern, so every radius reads back as the same float (NaN and −0 included).
            var at = radii.FindIndex(r => BitConverter.SingleToInt32Bits(r) == BitConverter.SingleToInt32Bits(p.Radius));
            if (at < 0)
            {
                if (radii.Count > byte.MaxValue) throw new ArgumentException($"more than {byte.MaxValue + 1} distinct probe radii", nameof(probes));
                at = radii.Count;
                radii.Add(p.Radius);
            }
            _radiusIndex[i] = (byte)at;
        }
        _radii = [.. radii];
    }

    public int Count => _centers.Length;

    public Probe this[int index] => new(_centers[index], _radii[_radiusIndex[index]], (ProbeKind)_kinds[index]);

    public IEnumerator<Probe> GetEnumerator()
    {
        for (var i = 0; i < _centers.Length; i++) yield return this[i];
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
