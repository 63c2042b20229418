using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// The whole-scene positions read on demand are the probes each moved into the landblock by its own
/// segment's frame, in segment order, by index and by enumeration alike (what a materialised list held).
/// </summary>
public sealed class ScenePositionsTests
{
    private static readonly PartPose Turned = new(new Vector3(10f, -4f, 2f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.7f), 1f);
    private static readonly PartPose Moved = new(new Vector3(-3f, 8f, 0f), Quaternion.Identity, 1f);

    private static Probe[] Probes(int count, float x) =>
        [.. Enumerable.Range(0, count).Select(i => new Probe(new Vector3(x + i, i * 0.5f, 1f), 0.48f + i * 0.01f, i % 2 == 0 ? ProbeKind.Grid : ProbeKind.Vertex))];

    [Fact]
    public void Every_position_is_its_probe_moved_by_its_segments_frame_in_order()
    {
        (IReadOnlyList<Probe> Probes, PartPose Frame)[] segments = [(Probes(3, 0f), Turned), ([], Moved), (Probes(1, 5f), Moved), (Probes(4, -2f), Turned)];
        var expected = segments.SelectMany(s => s.Probes.Select(p => p with { Center = s.Frame.ToEntity(p.Center) })).ToArray();

        var positions = new ScenePositions(segments);

        Assert.Equal(8, positions.Count);
        Assert.Equal(expected, positions.ToArray());
        Assert.Equal(expected, Enumerable.Range(0, positions.Count).Select(i => positions[i]).ToArray());
        Assert.NotEqual(segments[0].Probes[1].Center, positions[1].Center);
    }

    [Fact]
    public void An_index_outside_the_positions_is_refused()
    {
        var positions = new ScenePositions([(Probes(2, 0f), Moved)]);

        Assert.Throws<ArgumentOutOfRangeException>(() => positions[2]);
        Assert.Throws<ArgumentOutOfRangeException>(() => positions[-1]);
        Assert.Empty(new ScenePositions([]));
    }
}
