using System.Numerics;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Batch;
using AcShadow.Fixtures.Scenes;
using AcShadow.Tests.Chart;
using AcShadow.Tests.Forge;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// The compiled scene's whole-scene grid (<see cref="SceneReachGrid"/>) answers as the exhaustive walk over the same
/// entries, bit for bit: at every scene position, every position tangent to a bound or on a land-cell edge, the
/// corners of its voxels and a float step either side of them, and random positions through the grid's extent; on
/// the built-in sample (rotated cells, non-uniform part scales) and on a forged scale landblock.
/// </summary>
public sealed class SceneReachGridTests(SmallScaleFixture scale) : IClassFixture<SmallScaleFixture>
{
    private static readonly float[] Radii = [0.5f, 0.25f, 1.5f];

    [Fact]
    public void The_grid_answers_as_the_exhaustive_walk_on_the_sample_landblock()
    {
        var report = SceneCompileTests.Exact.Value;
        AssertSameAnswers(report, randomPositions: 200_000);
    }

    [Fact]
    public void The_grid_answers_as_the_exhaustive_walk_on_a_forged_scale_landblock()
    {
        Assert.True(LandblockIds.TryParse("0x0000", out var landblock));
        var scene = BatchPlanner.Plan(new BatchSelection(false, false, null, landblock), scale.Files.Portal, scale.Files.Cell, []).Scene!;
        var options = new SceneCompileOptions { Chart = new ChartOptions { Spacing = 1f } };
        var report = SceneCompiler.Compile(scene, new ChartSubjects(scale.Files.Portal), options, new FixedTimer());
        AssertSameAnswers(report, randomPositions: 200_000);
    }

    [Fact]
    public void A_program_budget_bounds_the_grid_and_keeps_its_answers()
    {
        Assert.True(LandblockIds.TryParse("0x0000", out var landblock));
        var scene = BatchPlanner.Plan(new BatchSelection(false, false, null, landblock), scale.Files.Portal, scale.Files.Cell, []).Scene!;
        var report = SceneCompiler.Compile(scene, new ChartSubjects(scale.Files.Portal), new SceneCompileOptions { Chart = new ChartOptions { Spacing = 1f } }, new FixedTimer());
        var query = SceneCompiler.Query(report.Placed, report.Compiled, report.Cells, c => c.Chosen, partsApart: true);
        var oracle = SceneCompiler.Query(report, c => c.Chosen).Exhaustive;
        var full = SceneReachGrid.Build([.. query.Objects], [.. query.Cells], [.. query.CellReaches], 0.5f)!;
        // No room for a program costing more than 16: those entries are asked whole, as before the longer bound.
        var bounded = SceneReachGrid.Build([.. query.Objects], [.. query.Cells], [.. query.CellReaches], 0.5f, programBudget: 0)!;
        Assert.True(bounded.Bytes < full.Bytes, $"bounded {bounded.Bytes} bytes, unbounded {full.Bytes}");
        var blocked = 0;
        foreach (var (at, _) in ScenePartitionTests.Positions(report))
        {
            var expected = oracle.Overlaps(at, 0.5f);
            Assert.True(expected == full.Overlaps(at) && expected == bounded.Overlaps(at), $"{at}: exhaustive {expected}");
            blocked += expected ? 1 : 0;
        }
        Assert.True(blocked > 0, "no position blocked");
    }

    [Fact]
    public void A_grid_query_allocates_nothing_and_settles_most_of_its_voxels()
    {
        var report = SceneCompileTests.Exact.Value;
        var query = SceneCompiler.Query(report.Placed, report.Compiled, report.Cells, c => c.Chosen, partsApart: true, gridRadii: [0.5f]);
        var grid = Assert.Single(query.Grids);
        var (clear, blocked, frontier, top) = grid.StateCounts();
        Assert.True(clear > 0 && blocked > 0 && frontier > 0, $"{clear} clear, {blocked} blocked, {frontier} frontier over {top} top cells");
        var probes = ScenePartitionTests.Positions(report).ToArray();
        var hits = 0;
        foreach (var (at, r) in probes) hits += query.Overlaps(at, r) ? 1 : 0;
        var before = GC.GetAllocatedBytesForCurrentThread();
        foreach (var (at, r) in probes) hits += query.Overlaps(at, r) ? 1 : 0;
        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.InRange(hits, 2, 2 * probes.Length - 2);
    }

    private static void AssertSameAnswers(CompiledSceneReport report, int randomPositions)
    {
        var oracle = SceneCompiler.Query(report, c => c.Chosen).Exhaustive;
        var query = SceneCompiler.Query(report.Placed, report.Compiled, report.Cells, c => c.Chosen, partsApart: true, gridRadii: Radii);
        Assert.Equal(Radii.Length, query.Grids.Count);
        var positions = ScenePartitionTests.Positions(report).Concat(ScenePartitionTests.EdgePositions(query)).ToList();
        // Voxel corners and a float step either side, around every entry's bound; then random centres over the scene.
        var random = new Random(31);
        var bounds = query.Objects.Select(o => o.LandblockBound).ToArray();
        foreach (var r in Radii)
        {
            var edge = r / 4f;
            foreach (var (center, radius) in bounds)
                for (var k = 0; k < 40; k++)
                {
                    var corner = new Vector3(
                        MathF.Round((center.X + (random.NextSingle() * 2 - 1) * (radius + r)) / edge) * edge,
                        MathF.Round((center.Y + (random.NextSingle() * 2 - 1) * (radius + r)) / edge) * edge,
                        MathF.Round((center.Z + (random.NextSingle() * 2 - 1) * (radius + r)) / edge) * edge);
                    positions.Add((corner, r));
                    positions.Add((new Vector3(MathF.BitDecrement(corner.X), MathF.BitDecrement(corner.Y), MathF.BitDecrement(corner.Z)), r));
                    positions.Add((new Vector3(MathF.BitIncrement(corner.X), MathF.BitIncrement(corner.Y), MathF.BitIncrement(corner.Z)), r));
                }
        }
        float x0 = bounds.Min(b => b.Center.X - b.Radius) - 2, x1 = bounds.Max(b => b.Center.X + b.Radius) + 2;
        float y0 = bounds.Min(b => b.Center.Y - b.Radius) - 2, y1 = bounds.Max(b => b.Center.Y + b.Radius) + 2;
        float z0 = bounds.Min(b => b.Center.Z - b.Radius) - 2, z1 = bounds.Max(b => b.Center.Z + b.Radius) + 2;
        for (var i = 0; i < randomPositions; i++)
        {
            // Half of them near a bound, where the grid's frontiers are.
            var (center, radius) = bounds[random.Next(bounds.Length)];
            var at = i % 2 == 0
                ? new Vector3(x0 + random.NextSingle() * (x1 - x0), y0 + random.NextSingle() * (y1 - y0), z0 + random.NextSingle() * (z1 - z0))
                : center + (radius + 1f) * new Vector3(random.NextSingle() * 2 - 1, random.NextSingle() * 2 - 1, random.NextSingle() * 2 - 1);
            positions.Add((at, Radii[i % Radii.Length]));
        }
        int blocked = 0, gridded = 0;
        foreach (var (at, r) in positions)
        {
            var expected = oracle.Overlaps(at, r);
            Assert.True(expected == query.Overlaps(at, r), $"{at} r {r}: exhaustive {expected}");
            if (expected) blocked++;
            if (Array.IndexOf(Radii, r) >= 0) gridded++;
        }
        Assert.InRange(blocked, positions.Count / 100, positions.Count - positions.Count / 100);
        Assert.True(gridded > positions.Count / 2, $"{gridded} of {positions.Count} asked through a grid");
    }
}
