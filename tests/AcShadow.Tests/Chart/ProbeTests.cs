using System.Numerics;
using AcShadow.Analysis.Chart;

namespace AcShadow.Tests.Chart;

public class ProbeTests
{
    [Fact]
    public void The_grid_sits_on_the_spacing_and_has_a_layer_at_walking_height()
    {
        var options = new ChartOptions();
        var grid = ProbeGrid.Build(new Bounds(new Vector3(-1, -0.2f, 0), new Vector3(1, 0.2f, 2.2f)), options);
        Assert.Equal(0.25f, grid.Spacing);
        Assert.All(grid.Probes, p => Assert.Equal(0f, MathF.IEEERemainder(p.Center.X, 0.25f), 5));
        Assert.Contains(grid.Probes, p => p.Center.Z == options.EffectiveWalkHeight);
        Assert.All(grid.Probes, p => Assert.Equal(0.5f, p.Radius));
        Assert.Contains(grid.Probes, p => p.Center.X <= -1.5f);
        Assert.Contains(grid.Probes, p => p.Center.Z >= 2.75f);
    }

    [Fact]
    public void A_grid_too_large_is_coarsened_and_says_so()
    {
        var grid = ProbeGrid.Build(new Bounds(new Vector3(-50, -50, 0), new Vector3(50, 50, 20)), new ChartOptions { MaxGridProbes = 10_000 });
        Assert.True(grid.Probes.Count <= 10_000);
        Assert.True(grid.Spacing > 0.25f);
    }

    [Fact]
    public void Stability_probes_past_their_limit_are_laid_more_coarsely_and_say_so()
    {
        int Stability(ObjectChart chart) => chart.Probes.Count(p => ProbeKinds.Stability.Contains(p.Kind));
        var full = Assert.Single(SampleChart.Run(new ChartOptions(), SampleChart.Door).Objects);
        Assert.DoesNotContain(full.Notes, n => n.StartsWith("stability-coarsened", StringComparison.Ordinal));

        // A limit below what the door needs at 0.25 m: faces and edges are sampled more coarsely until it fits.
        var limit = Stability(full) / 3;
        var capped = Assert.Single(SampleChart.Run(new ChartOptions { MaxStabilityProbes = limit }, SampleChart.Door).Objects);

        Assert.InRange(Stability(capped), 1, limit);
        // Every vertex and splitting plane is still probed; only the points laid along faces and edges thin out.
        Assert.Equal(ProbeCount(full, ProbeKind.Vertex), ProbeCount(capped, ProbeKind.Vertex));
        Assert.Equal(ProbeCount(full, ProbeKind.SplittingPlane), ProbeCount(capped, ProbeKind.SplittingPlane));
        Assert.Contains(capped.Notes, n => n.StartsWith("stability-coarsened: stability probes laid every ", StringComparison.Ordinal) && n.Contains($"under {limit} probes"));
        Assert.NotNull(new ChartOptions { MaxStabilityProbes = 0 }.Problem());
    }

    private static int ProbeCount(ObjectChart chart, ProbeKind kind) => chart.Probes.Count(p => p.Kind == kind);

    [Fact]
    public void Doorway_lines_cross_slab_footprints_only()
    {
        var options = new ChartOptions();
        var door = DoorwayProbes.Find(new Bounds(new Vector3(-1.1f, -0.15f, 0), new Vector3(1.1f, 0.15f, 2.3f)));
        Assert.NotNull(door);
        Assert.True(door.AcrossIsY);
        var probes = DoorwayProbes.Build(door, options);
        Assert.Equal(options.DoorwayOffsets.Count, probes.Select(p => p.Line).Distinct().Count());
        Assert.All(probes, p => Assert.Equal(options.EffectiveWalkHeight, p.Center.Z));
        Assert.Contains(probes, p => p.Center.Y < -0.6f);
        Assert.Contains(probes, p => p.Center.Y > 0.6f);
        Assert.Null(DoorwayProbes.Find(new Bounds(new Vector3(-5, -4, 0), new Vector3(5, 4, 6))));    // a house
        Assert.Null(DoorwayProbes.Find(new Bounds(new Vector3(-0.1f, -0.1f, 0), new Vector3(0.1f, 0.1f, 1))));  // a post
    }

    [Fact]
    public void Bad_options_are_refused_with_a_reason()
    {
        Assert.Contains("probe radius", new ChartOptions { ProbeRadius = -1 }.Problem());
        Assert.Contains("spacing", new ChartOptions { Spacing = 0 }.Problem());
        // A stability probe inside the frame arithmetic's tie band could be answered either way.
        Assert.Contains("tie band", new ChartOptions { StabilityOffset = ChartOptions.FrameArithmeticTie }.Problem());
        Assert.Null(new ChartOptions { StabilityOffset = 2.5e-5f }.Problem());
        Assert.Null(new ChartOptions().Problem());
        Assert.Throws<ArgumentException>(() => SampleChart.Run(new ChartOptions { Spacing = float.NaN }, SampleChart.Door));
    }
}
