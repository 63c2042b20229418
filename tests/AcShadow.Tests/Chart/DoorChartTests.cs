using System.Text;
using AcShadow.Core.Chart;
using AcShadow.Core.Chart.Output;

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
        Assert.Equal(0, fallback.FalseBlock);
    }

    [Fact]
    public void Both_svgs_show_the_door_result()
    {
        var files = ChartFiles.Render(SampleChart.DoorOnly).ToDictionary(f => f.RelativePath, f => Encoding.UTF8.GetString(f.Content));
        var fallback = Model("fallback-cylinder");
        Assert.Contains($"fallback-cylinder ({fallback.FalsePass} false passes)", files["speed-accuracy.svg"]);
        var map = files["failure-map-0x020019FF.svg"];
        Assert.Contains("fallback-cylinder", map);
        Assert.Contains("fill=\"#d62728\"", map); // false-pass cells are drawn
        Assert.Contains("false pass: reference blocks, model lets through", map);
        Assert.Contains("x (m)", map);
    }

    [Fact]
    public void Union_agrees_with_retail_on_the_door_and_part_spheres_only_over_block()
    {
        Assert.True(Model("union").Exact);
        Assert.Equal(0, Model("part-spheres").FalsePass);
        Assert.True(Model("part-spheres").FalseBlock > 0);
    }

    [Fact]
    public void Failures_list_the_disagreements_nearest_the_boundary_first()
    {
        var fallback = Model("fallback-cylinder");
        Assert.Equal(SampleChart.DoorOnly.Options.FailuresPerModel, fallback.Nearest.Count);
        Assert.All(fallback.Nearest, d => Assert.True(d.FalsePass));
        for (var k = 1; k < fallback.Nearest.Count; k++) Assert.True(fallback.Nearest[k - 1].Nearness <= fallback.Nearest[k].Nearness);
        var csv = Encoding.UTF8.GetString(ChartFiles.Render(SampleChart.DoorOnly).Single(f => f.RelativePath == "failures.csv").Content);
        Assert.StartsWith(FailuresCsv.Header + "\n", csv);
        Assert.Contains("0x020019FF,fallback-cylinder,1,false_pass,", csv);
    }

    [Fact]
    public void The_cheapest_exact_model_is_named()
    {
        // With the fixed timer retail (400 ns) beats union (420 ns); both are exact on the door.
        Assert.Equal("retail", Door.CheapestExact);
        var chart = Encoding.UTF8.GetString(ChartFiles.Render(SampleChart.DoorOnly).Single(f => f.RelativePath == "chart.csv").Content);
        Assert.Contains("0x020019FF,retail,3,", chart);
        Assert.Equal(1 + 6, chart.Split('\n', StringSplitOptions.RemoveEmptyEntries).Length);
    }
}
