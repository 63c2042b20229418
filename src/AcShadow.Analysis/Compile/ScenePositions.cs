using System.Collections;
using AcShadow.Analysis.Chart;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// The mover positions a whole scene is asked at: each placed object's probes moved into the landblock by
/// its frame, then each cell's by the cell's, in that order. Each position is moved when it is read, never
/// stored: the scale dat's busy landblock has 8.7 million of them, 244 MB as an array, and a list grown to
/// that size had held a 470 MB array beside the 235 MB one it was copied from.
/// </summary>
internal sealed class ScenePositions : IReadOnlyList<Probe>
{
    private readonly (IReadOnlyList<Probe> Probes, PartPose Frame)[] _segments;

    /// <summary>The index of each segment's first position.</summary>
    private readonly int[] _starts;

    public ScenePositions(IReadOnlyList<(IReadOnlyList<Probe> Probes, PartPose Frame)> segments)
    {
        _segments = [.. segments.Where(s => s.Probes.Count > 0)];
        _starts = new int[_segments.Length];
        var count = 0L;
        for (var i = 0; i < _segments.Length; i++)
        {
            _starts[i] = (int)count;
            count += _segments[i].Probes.Count;
        }
        Count = count <= int.MaxValue ? (int)count : throw new ArgumentException($"{count} positions: more than one list can index", nameof(segments));
    }

    public int Count { get; }

    public Probe this[int index]
    {
        get
        {
            ArgumentOutOfRangeException.ThrowIfNegative(index);
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, Count);
            var at = Array.BinarySearch(_starts, index);
            // Not a segment's first position: the segment before the insertion point holds it.
            var segment = at >= 0 ? at : ~at - 1;
            var (probes, frame) = _segments[segment];
            return Moved(probes[index - _starts[segment]], frame);
        }
    }

    public IEnumerator<Probe> GetEnumerator()
    {
        foreach (var (probes, frame) in _segments)
            for (var i = 0; i < probes.Count; i++)
                yield return Moved(probes[i], frame);
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

    private static Probe Moved(Probe probe, PartPose frame) => probe with { Center = frame.ToEntity(probe.Center) };
}
