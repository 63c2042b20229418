using System.Text;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Output;

namespace AcShadow.Tests.Chart;

/// <summary>What the seed describes, on the sample door 0x020019FF: the soda-can cylinder lets players through the closed doorway off-centre; retail blocks them.</summary>
public class DoorChartTests
{
    private static ObjectChart Door => SampleChart.DoorOnly.Objects.Single();
    private static ModelOutcome Model(string name) => Door.Models.Single(m => m.Model == name);

    [Fact]
    public void Retail_is_the_reference_and_blocks_the_closed_doorway_on_every_line()
    {
        Assert.Equal("retail", SampleChart.DoorOnly.Reference);
        Assert.True(Model("retail").Exact);
        Assert.NotNull(Door.Doorway);
        // Every doorway line crosses the closed leaf or a jamb: retail blocks some probe on each line.
        foreach (var line in Enumerable.Range(0, Door.Probes.Count).Where(i => Door.Probes[i].Kind == ProbeKind.Doorway).GroupBy(i => Door.Probes[i].Line))
            Assert.Contains(line, i => Door.Reference[i]);
    }

    [Fact]
    public void Fallback_cylinder_lets_probes_through_the_closed_doorway_off_centre()
    {
        var fallback = Model("fallback-cylinder");
        Assert.True(fallback.DoorwayFalsePass > 0);
        var falsePasses = Enumerable.Range(0, Door.Probes.Count)
            .Where(i => Door.Probes[i].Kind == ProbeKind.Doorway && Door.Reference[i] && !fallback.Answers[i])
            .Select(i => Door.Probes[i]).ToArray();
        // Off-centre (half a metre and more to the side) every line crosses the door where the soda can lets it through ...
        var offCentreLines = Door.Probes.Where(p => p.Kind == ProbeKind.Doorway && MathF.Abs(p.Offset) >= 0.5f).Select(p => p.Line).Distinct().ToArray();
        Assert.True(offCentreLines.Length >= 4);
        foreach (var line in offCentreLines) Assert.Contains(falsePasses, p => p.Line == line);
        // ... while on the centre line, at the door plane, it blocks like retail.
        var centre = Enumerable.Range(0, Door.Probes.Count).Where(i => Door.Probes[i].Kind == ProbeKind.Doorway && Door.Probes[i].Offset == 0f)
            .OrderBy(i => MathF.Abs(Door.Probes[i].Center.Y)).First();
        Assert.True(Door.Reference[centre] && fallback.Answers[centre]);
        Assert.Equal(0, fallback.DoorwayFalseBlock);
    }

    [Fact]
    public void Both_svgs_show_the_door_result()
    {
        var files = SampleChart.DoorOnly.Files.ToDictionary(f => f.RelativePath, f => Encoding.UTF8.GetString(f.Content.Span));
        var fallback = Model("fallback-cylinder");
        Assert.Contains($"fallback-cylinder ({fallback.FalsePass} false passes)", files["speed-accuracy.svg"]);
        var map = files["failure-map-0x020019FF.svg"];
        Assert.Contains("fallback-cylinder", map);
        Assert.Contains("fill=\"#d62728\"", map); // false-pass cells are drawn
        Assert.Contains("false pass: reference blocks, model lets through", map);
        Assert.Contains("x (m)", map);
    }

    [Fact]
    public void Union_never_lets_a_mover_through_the_door_and_part_spheres_only_over_block()
    {
        // Union is retail's BSPs plus the door's Sphere as a cylinder, inside the leaf; only that cylinder's
        // square profile (CCylSphere tests a box in profile) blocks at a few stability probes beside the leaf's bottom edges.
        var union = Model("union");
        Assert.Equal(0, union.FalsePass);
        Assert.Equal(0, union.DoorwayFalseBlock);
        Assert.All(Enumerable.Range(0, Door.Probes.Count).Where(i => union.Answers[i] != Door.Reference[i]),
            i => Assert.True(ProbeKinds.IsStability(Door.Probes[i].Kind) && Door.Probes[i].Center.Z < 0f, $"probe {i}: {Door.Probes[i]}"));
        Assert.Equal(0, Model("part-spheres").FalsePass);
        Assert.True(Model("part-spheres").FalseBlock > 0);
    }

    [Fact]
    public void Failures_list_the_disagreements_nearest_the_boundary_first()
    {
        var fallback = Model("fallback-cylinder");
        var k = SampleChart.DoorOnly.Options.FailuresPerModel;
        Assert.Equal(Math.Min(k, fallback.FalsePass) + Math.Min(k, fallback.FalseBlock), fallback.Nearest.Count);
        // Stability probes put many false blocks within 0.1 mm of the boundary; the false passes still show.
        Assert.True(fallback.FalsePass > 0);
        Assert.Equal(Math.Min(k, fallback.FalsePass), fallback.Nearest.Count(d => d.FalsePass));
        for (var n = 1; n < fallback.Nearest.Count; n++) Assert.True(fallback.Nearest[n - 1].Nearness <= fallback.Nearest[n].Nearness);
        var csv = SampleChart.DoorOnly.Text("failures.csv");
        Assert.StartsWith(FailuresCsv.Header + "\n", csv);
        Assert.Contains("0x020019FF,fallback-cylinder,1,", csv);
    }

    [Fact]
    public void The_cheapest_exact_model_is_named()
    {
        // Retail is the only exact model of the door: its jambs carry thresholds (no box, no hull) and union's cylinder is square in profile.
        Assert.Equal("retail", Door.CheapestExact);
        var chart = SampleChart.DoorOnly.Text("chart.csv");
        Assert.Contains("0x020019FF,retail,3,", chart);
        Assert.Equal(1 + AcShadow.Analysis.Chart.Models.ShapeModels.All.Count, chart.Split('\n', StringSplitOptions.RemoveEmptyEntries).Length);
    }
}
