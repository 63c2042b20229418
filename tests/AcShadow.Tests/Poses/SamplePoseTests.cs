using System.Numerics;
using AcShadow.Analysis.Audit;
using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Poses;

/// <summary>
/// The sample's motion cases read from the forged dat. Expected part frames are the ones docs/forge-spec.md's
/// sample section and Sample/sample.json give for the animation frame retail starts on, worked out by hand.
/// </summary>
public class SamplePoseTests
{
    private static readonly float Half = MathF.Sqrt(0.5f);

    private static ShadowShapeSet Build(uint setup, PosePolicy pose = PosePolicy.Retail, DoorState state = DoorState.Closed, uint? table = null)
    {
        using var dat = SampleDat.OpenPortal();
        return ShadowShapeBuilder.Build(dat.ReadSetup(setup)!, dat.ReadGfxObj,
            new ShapeBuildOptions(ShapePolicy.Retail) { Pose = pose, DoorState = state, MotionTable = table }, dat);
    }

    private static void AssertAt(ShadowShape shape, Vector3 origin, Quaternion rotation)
    {
        Assert.True(Vector3.Distance(origin, shape.LocalPosition) < 1e-6f, $"part {shape.SourceIndex} at {shape.LocalPosition}, expected {origin}");
        Assert.True(Math.Abs(Quaternion.Dot(rotation, shape.LocalRotation)) > 1 - 1e-6f, $"part {shape.SourceIndex} turned {shape.LocalRotation}, expected {rotation}");
    }

    [Fact]
    public void The_closed_door_leaf_stands_where_the_off_cycle_frame_0_puts_it_not_at_resting()
    {
        // 0x09000202 (the catalog's table for 0x020019FF): DefaultStyle NonCombat, StyleDefaults[NonCombat] = Off,
        // Cycles[0x003D000C] = [0x03000100 frames 0..-1 at 30 fps] -> frame 0: leaf (0.05, 0, 0), jambs (1, 0, 0) and (-1, 0, 0) turned 180.
        var set = Build(0x020019FF);
        AssertAt(set.Shapes[0], new(0.05f, 0, 0), Quaternion.Identity);
        AssertAt(set.Shapes[1], new(1, 0, 0), Quaternion.Identity);
        AssertAt(set.Shapes[2], new(-1, 0, 0), new Quaternion(0, 0, 1, 0));
        Assert.Equal(new PoseProvenance("retail", PoseProvenance.MotionTableSource, 0x09000202, "door-catalog", MotionCommand.NonCombat, MotionCommand.Off,
            0x03000100, 0, "closed", false, true), set.Pose);
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.PoseMoved && d.Message.Contains("part 0 by 0.05 m"));

        var placement = Build(0x020019FF, PosePolicy.Placement);
        AssertAt(placement.Shapes[0], Vector3.Zero, Quaternion.Identity);
        Assert.Equal(PoseProvenance.PlacementSource, placement.Pose.Source);
        Assert.DoesNotContain(placement.Diagnostics, d => d.Code == PoseDiagnosticCodes.PoseMoved);
    }

    [Fact]
    public void The_open_door_swings_its_leaf_90_degrees_about_the_hinge_and_says_it_is_ethereal()
    {
        // Cycles[0x003D000B] = [0x03000101]: frame 0 puts the leaf at (0.965, -0.965, 0) turned 90 deg about Z,
        // so its hinge edge (local x 0.965) stays at (0.965, 0, 0).
        var set = Build(0x020019FF, state: DoorState.Open);
        AssertAt(set.Shapes[0], new(0.965f, -0.965f, 0), new Quaternion(0, 0, Half, Half));
        var hinge = set.Shapes[0].LocalPosition + Vector3.Transform(new Vector3(0.965f, 0, 0), set.Shapes[0].LocalRotation);
        Assert.True(Vector3.Distance(new Vector3(0.965f, 0, 0), hinge) < 1e-5f);
        Assert.Equal((MotionCommand.On, 0x03000101u, "open", true), (set.Pose.Substate, set.Pose.AnimationId, set.Pose.DoorState, set.Pose.Ethereal));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.OpenDoorEthereal);
    }

    [Fact]
    public void A_motion_table_missing_its_default_cycle_leaves_the_placement_pose_with_diagnostics()
    {
        // 0x09000016 names Off as NonCombat's default but holds only the On cycle: SetDefaultState fails.
        foreach (var state in new[] { DoorState.Closed, DoorState.Open })
        {
            var set = Build(0x0200024F, state: state);
            AssertAt(Assert.Single(set.Shapes), Vector3.Zero, Quaternion.Identity);
            Assert.Equal(PoseProvenance.PlacementSource, set.Pose.Source);
            Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.NoDefaultState && d.Message.Contains("0x003D000C"));
            Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.DoorMotion);
        }
    }

    [Fact]
    public void A_setup_with_only_a_default_animation_takes_its_first_frame()
    {
        // DefaultAnimation 0x03003600 frames [(0.3, 0, 0)], [(0.6, 0, 0)]: retail starts at frame 0.
        var set = Build(0x02003600);
        AssertAt(Assert.Single(set.Shapes), new(0.3f, 0, 0), Quaternion.Identity);
        Assert.Equal((PoseProvenance.DefaultAnimationSource, 0x03003600u, 0), (set.Pose.Source, set.Pose.AnimationId, set.Pose.Frame));
    }

    [Fact]
    public void An_animation_with_fewer_part_frames_poses_those_parts_and_leaves_the_rest_where_they_were_made()
    {
        // 0x09003500's Ready cycle plays 0x03003500 (1 part frame): pedestal at (0, 0, 0.25). UpdateParts stops at
        // part 0, and its first call (InitObjectEnd) already poses by the animation, so the column keeps its
        // CPhysicsPart frame, origin 0 and no rotation, not Resting's (0, 0, 0.5). The Setup's DefaultAnimation is
        // replaced by the table's default state.
        var set = Build(0x02003500);
        AssertAt(set.Shapes[0], new(0, 0, 0.25f), Quaternion.Identity);
        AssertAt(set.Shapes[1], Vector3.Zero, Quaternion.Identity);
        Assert.Equal((PoseProvenance.MotionTableSource, 0x09003500u, "setup", 0x03003500u), (set.Pose.Source, set.Pose.MotionTableId, set.Pose.MotionTableFrom, set.Pose.AnimationId));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.AnimationParts && d.Message.Contains("1 of the Setup's 2 parts"));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.PoseMoved && d.Message.Contains("part 1 by 0.5 m"));
    }

    [Fact]
    public void A_default_animation_short_of_part_frames_leaves_the_last_part_at_the_origin_unturned()
    {
        // 0x02003900: DefaultAnimation 0x03003900 (2 part frames, 1 frame) for 3 parts; no motion table.
        // Frame 0: pedestal (0, 0, 0.2), L-block (-0.3, -0.3, 0.95) turned 45 deg about Z. The column (Resting:
        // (0.6, 0.2, 1.0) turned 90 deg about X) gets no frame: origin 0, no rotation.
        var set = Build(0x02003900);
        Assert.Equal(3, set.Shapes.Count);
        AssertAt(set.Shapes[0], new(0, 0, 0.2f), Quaternion.Identity);
        AssertAt(set.Shapes[1], new(-0.3f, -0.3f, 0.95f), new Quaternion(0, 0, MathF.Sin(MathF.PI / 8), MathF.Cos(MathF.PI / 8)));
        AssertAt(set.Shapes[2], Vector3.Zero, Quaternion.Identity);
        Assert.Equal((PoseProvenance.DefaultAnimationSource, 0x03003900u, 0), (set.Pose.Source, set.Pose.AnimationId, set.Pose.Frame));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.AnimationParts && d.Message.Contains("2 of the Setup's 3 parts") && d.Message.Contains("part 2"));
    }

    [Fact]
    public void A_default_cycle_of_three_animations_is_posed_by_its_last_once_in_the_world()
    {
        // 0x09003700: Cycles[0x003D0003] = [0x03003701 at 30 fps, 0x03003702 at 30 fps, 0x03003703 at -30 fps].
        // add_motion makes 0x03003701 current (frame 0: x 0.1) and 0x03003703 first_cyclic; entering the world
        // drops the two before it, so 0x03003703 is current at its starting frame: backwards, HighFrame -1 -> 2 of
        // its 3 frames, and frame 2 is (0, 0, 0.3) turned 90 deg about Z.
        var set = Build(0x02003700);
        AssertAt(Assert.Single(set.Shapes), new(0, 0, 0.3f), new Quaternion(0, 0, Half, Half));
        Assert.Equal(new PoseProvenance("retail", PoseProvenance.MotionTableSource, 0x09003700, "setup", MotionCommand.NonCombat, MotionCommand.Ready,
            0x03003703, 2, null, false, true), set.Pose);
        Assert.DoesNotContain(set.Diagnostics, d => d.Code != PoseDiagnosticCodes.PoseMoved);
    }

    [Fact]
    public void A_door_whose_table_starts_in_hand_combat_takes_the_noncombat_style_before_its_substate()
    {
        // 0x0900002C (the catalog's table for 0x02000311): default state HandCombat Ready, Cycles[0x003C0003] =
        // [0x0300002C] (z 0.4). The NonCombat style command: StyleDefaults[NonCombat] = Off, Cycles[0x003D000C] =
        // [0x0300002D] after the link Links[0x003C0003][0x8000003D] = [0x0300002F], which is dropped; Off is then
        // already the substate. Frame 0 of 0x0300002D: (0.02, 0, 0). Without the style command Off would have
        // played Cycles[0x003C000C] = 0x0300002F, (0, 0, -1).
        var closed = Build(0x02000311);
        AssertAt(Assert.Single(closed.Shapes), new(0.02f, 0, 0), Quaternion.Identity);
        Assert.Equal(new PoseProvenance("retail", PoseProvenance.MotionTableSource, 0x0900002C, "door-catalog", MotionCommand.NonCombat, MotionCommand.Off,
            0x0300002D, 0, "closed", false, true), closed.Pose);
        Assert.DoesNotContain(closed.Diagnostics, d => d.Code == PoseDiagnosticCodes.DoorMotion);

        // Open: NonCombat Off as above, then On: Cycles[0x003D000B] = [0x0300002E], frame 0 (0, -0.5, 0) turned 90 deg about Z.
        var open = Build(0x02000311, state: DoorState.Open);
        AssertAt(Assert.Single(open.Shapes), new(0, -0.5f, 0), new Quaternion(0, 0, Half, Half));
        Assert.Equal((MotionCommand.NonCombat, MotionCommand.On, 0x0300002Eu, "open", true), (open.Pose.Style, open.Pose.Substate, open.Pose.AnimationId, open.Pose.DoorState, open.Pose.Ethereal));
    }

    [Fact]
    public void A_cycle_animation_missing_from_the_dat_never_joins_the_sequence()
    {
        // 0x09003800: Cycles[0x003D0003] = [0x03003801, 0x03003802 from LowFrame 1, 0x03003803]; 0x03003803 is not
        // in the dat, so append_animation drops it and 0x03003802 is first_cyclic: current once in the world, at
        // frame 1, (0, 0.7, 0). (ACE keeps an empty node for it instead, current, and poses nothing.)
        var set = Build(0x02003800);
        AssertAt(Assert.Single(set.Shapes), new(0, 0.7f, 0), Quaternion.Identity);
        Assert.Equal((0x03003802u, 1), (set.Pose.AnimationId, set.Pose.Frame));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.MissingAnimation && d.Message.Contains("0x03003803"));
    }

    [Fact]
    public void A_motion_table_named_on_the_command_line_replaces_the_catalogs()
    {
        // The door table on the single-part door: its Off frame poses part 0 at (0.05, 0, 0); the two extra
        // part frames are ignored, as UpdateParts poses min(parts, part frames).
        var set = Build(0x0200024F, table: 0x09000202);
        AssertAt(Assert.Single(set.Shapes), new(0.05f, 0, 0), Quaternion.Identity);
        Assert.Equal((0x09000202u, "option"), (set.Pose.MotionTableId, set.Pose.MotionTableFrom));
        Assert.DoesNotContain(set.Diagnostics, d => d.Code is PoseDiagnosticCodes.AnimationParts or PoseDiagnosticCodes.NoDefaultState);
    }

    [Fact]
    public void Audit_lists_exactly_the_sample_setups_whose_two_poses_differ()
    {
        using var portal = SampleDat.OpenPortal();
        var plan = BatchPlanner.Plan(new BatchSelection(false, true, null, null), portal, null, DoorCatalog.SetupIds);
        var report = AuditRunner.Run(portal, plan, new AuditQuery { PoseDiffers = true }, 2);
        // The style door, and the new rule Setups: each is posed away from its Resting frame at the origin.
        Assert.Equal([0x02000311u, 0x020019FFu, 0x02003500u, 0x02003600u, 0x02003700u, 0x02003800u, 0x02003900u], report.Rows.Select(r => r.SetupId));
        Assert.Equal(["motion-table", "motion-table", "motion-table", "default-animation", "motion-table", "motion-table", "default-animation"], report.Rows.Select(r => r.PoseSource));
    }

    [Fact]
    public void Each_motion_table_and_animation_is_decoded_once_however_many_setups_share_it()
    {
        using var portal = SampleDat.OpenPortal();
        var engine = new ExportEngine(portal, new ShapeBuildOptions(ShapePolicy.Retail));
        foreach (var id in portal.ListIds(DatObjectKind.Setup)) engine.ExportSetup(id);
        var distinct = portal.MotionObjectsDecoded;
        // Read: the three tables (0x09000016 serves two doors), the closed door frame 0x03000100, 0x03003500, and
        // 0x03003600 (the DefaultAnimation of two Setups): 6. Never needed closed: the open, swing and unreachable animations.
        // The rule Setups add 12: 0x09003700 and its three animations; 0x0900002C with its HandCombat Ready
        // animation, the link 0x0300002F and NonCombat's Off cycle 0x0300002D (not the open 0x0300002E);
        // 0x09003800 and the two animations it has (the absent 0x03003803 decodes nothing); 0x03003900.
        Assert.Equal(18, distinct);
        foreach (var id in portal.ListIds(DatObjectKind.Setup)) engine.ExportSetup(id);
        Assert.Equal(distinct, portal.MotionObjectsDecoded);
    }

    [Fact]
    public void A_whole_dat_batch_on_two_jobs_with_a_bounded_cache_decodes_each_motion_object_once()
    {
        // As batch runs: two workers, and a GfxObj/Setup cache smaller than the dat; the motion objects stay.
        using var portal = SampleDat.OpenPortal();
        var source = new DatDatabase(portal.Archive, cacheCapacity: 2);
        var selection = new BatchSelection(true, true, null, null);
        var plan = BatchPlanner.Plan(selection, source, null, DoorCatalog.SetupIds);
        var options = new ShapeBuildOptions(ShapePolicy.Retail);
        var result = BatchRunner.Run(source, options, plan, new BatchInputs(source.Info, null, options.Policy, 1f, selection), jobs: 2);
        Assert.Equal(portal.ListIds(DatObjectKind.Setup).Count, result.SetupsWritten);
        Assert.Equal(18, source.MotionObjectsDecoded);
    }
}
