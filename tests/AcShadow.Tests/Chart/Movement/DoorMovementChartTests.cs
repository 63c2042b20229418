using AcShadow.Analysis.Chart.Movement;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>The movement chart on the sample door 0x020019FF (issue 29's "done when").</summary>
public class DoorMovementChartTests
{
    private static ObjectMovementChart Door => SampleMovementChart.Door;
    private static ModelMovement Model(string name) => Door.Models.Single(m => m.Model == name);
    private static int Walk => Door.Cases.Select(c => c.Id).ToList().IndexOf(SampleMovementChart.OffsetWalk);

    [Fact]
    public void The_cases_are_the_ones_move_writes_and_retail_walked_as_primitives_reproduces_every_frame()
    {
        Assert.Equal(616, Door.Cases.Count);
        var retail = Model("retail");
        Assert.All(retail.Verdicts, v => Assert.Equal(MovementVerdict.Agree, v));
        Assert.All(retail.FirstDivergingFrames, f => Assert.Null(f));
        Assert.Equal(MovementOutcome.Blocked, Door.Cases[Walk].Outcome.Class);
    }

    [Fact]
    public void The_fallback_cylinder_lets_the_player_past_the_closed_door_on_the_offset_walk()
    {
        var fallback = Model("fallback-cylinder");
        Assert.Equal(MovementVerdict.FalsePass, fallback.Verdicts[Walk]);
        Assert.True(fallback.FalsePasses > 0);
        // The open door is ethereal: whatever the model, every walk goes through, as retail's does.
        var open = Enumerable.Range(0, Door.Cases.Count).Where(i => Door.Cases[i].State == "open").ToArray();
        Assert.Equal(308, open.Length);
        Assert.All(Door.Models, m => Assert.All(open, i => Assert.Equal(MovementVerdict.Agree, m.Verdicts[i])));
    }

    [Fact]
    public void Every_model_gets_a_verdict_on_every_case_and_the_walk_is_kept_for_each()
    {
        Assert.Equal(["retail", "union", "fallback-cylinder", "spheres", "part-spheres", "part-boxes", "part-hulls", "placement-pose"], Door.Models.Select(m => m.Model));
        Assert.All(Door.Models, m => Assert.Equal(Door.Cases.Count, m.Verdicts.Count));
        Assert.Equal(3, Model("part-boxes").Shapes);
        Assert.Equal(3, Model("part-hulls").Shapes);
        var (index, frames) = Door.Walk!.Value;
        Assert.Equal(Walk, index);
        Assert.Equal(Door.Models.Count, frames.Count);
        Assert.Equal(Door.Cases[Walk].Expected.Select(f => (f.Position, f.Valid, f.Contact)), frames[0].Select(f => (f.Position, f.Valid, f.Contact)));
    }
}
