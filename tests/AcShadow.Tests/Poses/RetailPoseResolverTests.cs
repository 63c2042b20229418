using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Tests.Support.Records;

namespace AcShadow.Tests.Poses;

/// <summary>The creation rules of motion-pose.md on in-memory objects the sample does not carry.</summary>
public class RetailPoseResolverTests
{
    private sealed class Motions(params object[] objects) : IMotionSource
    {
        public MotionTable? ReadMotionTable(uint id) => objects.OfType<MotionTable>().FirstOrDefault(t => t.Id == id);
        public Animation? ReadAnimation(uint id) => objects.OfType<Animation>().FirstOrDefault(a => a.Id == id);
    }

    /// <summary>An animation of one part whose frame i puts the part at x = i.</summary>
    private static Animation Steps(uint id, int frames) =>
        new(id, 0, 1, null, Enumerable.Range(0, frames).Select(i => new AnimationFrame([new Frame(new Vector3(i, 0, 0), Quaternion.Identity)], [])).ToArray());

    private static MotionTable Table(uint id, params AnimData[] cycle) => new(id, MotionCommand.NonCombat,
        [new(MotionCommand.NonCombat, MotionCommand.Ready)],
        [new(MotionCommand.Key(MotionCommand.NonCombat, MotionCommand.Ready), new MotionData(0, cycle, null, null))], [], []);

    private static readonly Setup OnePart = Setup(0x02000F00, [0x01000F00], [PlacementAt(Placement.Resting, new Vector3(0, 0, 7))]);

    private static (ResolvedPose Pose, List<Diagnostic> Diagnostics) Resolve(Setup setup, IMotionSource motions)
    {
        var diagnostics = new List<Diagnostic>();
        return (RetailPoseResolver.Resolve(setup, new ShapeBuildOptions(ShapePolicy.Retail).PoseSettings, motions, diagnostics), diagnostics);
    }

    [Theory]
    // LowFrame, HighFrame, framerate -> frame posed (10 frames): forward starts at LowFrame, backward at HighFrame.
    [InlineData(3, -1, 30f, 3)]
    [InlineData(3, -1, -30f, 9)]       // HighFrame -1 -> last frame, played backwards from it
    [InlineData(2, 6, -30f, 6)]
    [InlineData(12, -1, 30f, 9)]       // LowFrame past the end -> last frame
    [InlineData(7, 4, -30f, 7)]        // LowFrame > HighFrame -> HighFrame = LowFrame
    [InlineData(-2, 5, 30f, 9)]        // retail compares LowFrame unsigned: -2 is past the end
    public void The_default_cycle_starts_at_the_clamped_starting_frame(int low, int high, float rate, int expected)
    {
        var setup = OnePart with { DefaultMotionTable = 0x09000F00 };
        var (pose, diagnostics) = Resolve(setup, new Motions(Table(0x09000F00, new AnimData(0x03000F00, low, high, rate)), Steps(0x03000F00, 10)));
        Assert.DoesNotContain(diagnostics, d => d.Code != PoseDiagnosticCodes.PoseMoved);
        Assert.Equal(expected, pose.Provenance.Frame);
        Assert.Equal(new Vector3(expected, 0, 0), pose.MotionFrames![0].Position);
    }

    [Fact]
    public void A_working_motion_table_replaces_the_default_animation_and_a_failing_one_keeps_it()
    {
        var works = OnePart with { DefaultAnimation = 0x03000F01, DefaultMotionTable = 0x09000F00 };
        var objects = new object[] { Table(0x09000F00, new AnimData(0x03000F00, 4, -1, 30f)), Steps(0x03000F00, 10), Steps(0x03000F01, 10) };
        Assert.Equal((0x03000F00u, 4), (Resolve(works, new Motions(objects)).Pose.Provenance.AnimationId, Resolve(works, new Motions(objects)).Pose.Provenance.Frame));

        var failing = new MotionTable(0x09000F02, MotionCommand.NonCombat, [new(MotionCommand.NonCombat, MotionCommand.Ready)], [], [], []);
        var (pose, diagnostics) = Resolve(works with { DefaultMotionTable = 0x09000F02 }, new Motions([.. objects, failing]));
        Assert.Equal((PoseProvenance.DefaultAnimationSource, 0x03000F01u, 0), (pose.Provenance.Source, pose.Provenance.AnimationId, pose.Provenance.Frame));
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.NoDefaultState && d.Message.Contains("DefaultAnimation"));
    }

    [Fact]
    public void A_missing_animation_is_dropped_and_the_next_one_becomes_current()
    {
        var setup = OnePart with { DefaultMotionTable = 0x09000F00 };
        var (pose, diagnostics) = Resolve(setup, new Motions(Table(0x09000F00, new AnimData(0x03000F09, 0, -1, 30f), new AnimData(0x03000F00, 2, -1, 30f)), Steps(0x03000F00, 10)));
        Assert.Equal((0x03000F00u, 2), (pose.Provenance.AnimationId, pose.Provenance.Frame));
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.MissingAnimation && d.Message.Contains("0x03000F09"));
    }

    [Fact]
    public void An_animation_without_frames_and_an_empty_cycle_and_a_missing_table_fall_back_to_the_placement_pose()
    {
        var setup = OnePart with { DefaultMotionTable = 0x09000F00 };
        var cases = new (IMotionSource Motions, string Code)[]
        {
            (new Motions(Table(0x09000F00, new AnimData(0x03000F00, 0, -1, 30f)), Steps(0x03000F00, 0)), PoseDiagnosticCodes.AnimationFrame),
            (new Motions(Table(0x09000F00)), PoseDiagnosticCodes.NoDefaultState),
            (new Motions(), PoseDiagnosticCodes.MissingMotionTable),
        };
        foreach (var (motions, code) in cases)
        {
            var (pose, diagnostics) = Resolve(setup, motions);
            Assert.Null(pose.MotionFrames);
            Assert.Equal(PoseProvenance.PlacementSource, pose.Provenance.Source);
            Assert.Equal(new Vector3(0, 0, 7), pose.Placement!.Frames[0].Position);
            Assert.Contains(diagnostics, d => d.Code == code);
        }
    }
    [Fact]
    public void A_door_whose_off_cycle_animation_is_absent_is_left_on_its_link()
    {
        // Table: NonCombat starts On (Cycles[0x003D000B] = [0x03000F00 forward], x = 0); Cycles[0x003D000C] = [0x03000F09],
        // not in the dat; Links[0x003D000B][Off] = [0x03000F01 at -30 fps]. Closing: remove_cyclic_anims drops the On
        // node (current, with none before it), the link is appended and becomes current, the Off cycle appends
        // nothing, so the link is first_cyclic: backwards from HighFrame -1 -> 4 of its 5 frames, x = 4.
        var on = MotionCommand.Key(MotionCommand.NonCombat, MotionCommand.On);
        var table = new MotionTable(0x09000F00, MotionCommand.NonCombat, [new(MotionCommand.NonCombat, MotionCommand.On)],
            [new(on, new MotionData(0, [new AnimData(0x03000F00, 0, -1, 30f)], null, null)),
             new(MotionCommand.Key(MotionCommand.NonCombat, MotionCommand.Off), new MotionData(0, [new AnimData(0x03000F09, 0, -1, 30f)], null, null))],
            [], [new(on, [new(MotionCommand.Off, new MotionData(0, [new AnimData(0x03000F01, 0, -1, -30f)], null, null))])]);
        var door = OnePart with { Id = 0x020019FF };
        var diagnostics = new List<Diagnostic>();
        var settings = new ShapeBuildOptions(ShapePolicy.Retail) { MotionTable = 0x09000F00 }.PoseSettings;
        var pose = RetailPoseResolver.Resolve(door, settings, new Motions(table, Steps(0x03000F00, 3), Steps(0x03000F01, 5)), diagnostics);
        Assert.Equal((0x03000F01u, 4, MotionCommand.Off, "closed"), (pose.Provenance.AnimationId, pose.Provenance.Frame, pose.Provenance.Substate, pose.Provenance.DoorState));
        Assert.Equal(new Vector3(4, 0, 0), pose.MotionFrames![0].Position);
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.MissingAnimation && d.Message.Contains("0x03000F09"));
        Assert.Contains(diagnostics, d => d.Code == PoseDiagnosticCodes.DoorMotion && d.Message.Contains("link"));
    }
}
