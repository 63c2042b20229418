using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Forge;

namespace AcShadow.Tests.Poses;

/// <summary>
/// The pose rules on the `forge scale` dat: the tables ScaleMotions gives one Setup each. Expected frames are
/// worked out by hand from the tables and animations docs/forge-spec.md describes (part p of every rule
/// animation frame at (x, y, 0.1 p)).
/// </summary>
[Trait("Speed", "Slow")]
public sealed class ScalePoseRuleTests(SmallScaleFixture fixture) : IClassFixture<SmallScaleFixture>
{
    private (Setup Setup, ResolvedPose Pose, List<Diagnostic> Diagnostics) Resolve(Func<Setup, bool> which)
    {
        var portal = fixture.Files.Portal;
        var setup = portal.ListIds(DatObjectKind.Setup).Select(id => portal.ReadSetup(id)!).Single(which);
        var diagnostics = new List<Diagnostic>();
        return (setup, RetailPoseResolver.Resolve(setup, new ShapeBuildOptions(ShapePolicy.Retail).PoseSettings, portal, diagnostics), diagnostics);
    }

    /// <summary>The pose of each of the Setup's parts (a 30-part animation also has frames past them, which pose nothing).</summary>
    private static void AssertParts(ResolvedPose pose, int parts, Func<int, Vector3> expected)
    {
        Assert.True(pose.MotionFrames!.Count >= parts, $"{pose.MotionFrames.Count} part frames for {parts} parts");
        for (var p = 0; p < parts; p++)
        {
            Assert.True(Vector3.Distance(expected(p), pose.MotionFrames[p].Position) < 1e-6f, $"part {p} at {pose.MotionFrames[p].Position}, expected {expected(p)}");
            Assert.Equal(Quaternion.Identity, pose.MotionFrames[p].Rotation);
        }
    }

    [Fact]
    public void The_three_animation_cycle_is_posed_by_its_last_animation_backwards_from_its_last_frame()
    {
        // 0x09000F01 Ready: [0x03000F01, 0x03000F02, 0x03000F03 at -30 fps]; 0x03000F03 has 3 frames, (0.3, 0.1 (f + 1), 0.1 p):
        // backwards it starts at frame 2, (0.3, 0.3, 0.1 p).
        var (setup, pose, _) = Resolve(s => s.DefaultMotionTable == 0x09000F01);
        Assert.Equal((0x03000F03u, 2), (pose.Provenance.AnimationId, pose.Provenance.Frame));
        AssertParts(pose, setup.Parts.Count, p => new(0.3f, 0.3f, 0.1f * p));
    }

    [Fact]
    public void The_cycle_with_an_absent_last_animation_is_posed_by_the_one_before_it()
    {
        // 0x09000F02 Ready: [0x03000F04, 0x03000F05 from frame 1, 0x03000F06 (absent)]: 0x03000F05 frame 1, (0, 0.5, 0.1 p).
        var (setup, pose, diagnostics) = Resolve(s => s.DefaultMotionTable == 0x09000F02);
        Assert.Equal((0x03000F05u, 1), (pose.Provenance.AnimationId, pose.Provenance.Frame));
        AssertParts(pose, setup.Parts.Count, p => new(0, 0.5f, 0.1f * p));
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.MissingAnimation && d.Message.Contains("0x03000F06"));
    }

    [Fact]
    public void The_short_animation_poses_part_0_and_leaves_the_rest_at_the_origin()
    {
        // 0x09000F03 Ready: [0x03000F07], one part frame (0.05, 0.05, 0); every other part keeps origin 0, no rotation.
        var (setup, pose, diagnostics) = Resolve(s => s.DefaultMotionTable == 0x09000F03);
        Assert.True(setup.Parts.Count >= 2);
        AssertParts(pose, setup.Parts.Count, p => p == 0 ? new(0.05f, 0.05f, 0) : Vector3.Zero);
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.AnimationParts);
    }

    [Fact]
    public void The_door_whose_table_starts_in_hand_combat_closes_by_noncombat_off()
    {
        // 0x0900002C: HandCombat Ready plays the open frames (the door's Default placement); NonCombat's default
        // is Off, whose cycle plays the closed frames (its Resting placement). Skipping the style command there
        // is no HandCombat Off cycle, and the door would stay open.
        var (setup, pose, diagnostics) = Resolve(s => s.Id == 0x02000311);
        var resting = setup.FindPlacement(Placement.Resting)!.Frames;
        Assert.Equal((MotionCommand.NonCombat, MotionCommand.Off, "closed"), (pose.Provenance.Style, pose.Provenance.Substate, pose.Provenance.DoorState));
        Assert.Equal(resting.Select(f => (f.Position, f.Rotation)), pose.MotionFrames!.Select(f => (f.Position, f.Rotation)));
        Assert.DoesNotContain(diagnostics, d => d.Code == PoseDiagnosticCodes.DoorMotion);
    }
}
