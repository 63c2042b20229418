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
    public void An_animation_with_fewer_part_frames_poses_those_parts_and_leaves_the_rest_at_placement()
    {
        // 0x09003500's Ready cycle plays 0x03003500 (1 part frame): pedestal at (0, 0, 0.25); the column keeps
        // Resting's (0, 0, 0.5). The Setup's DefaultAnimation is replaced by the table's default state.
        var set = Build(0x02003500);
        AssertAt(set.Shapes[0], new(0, 0, 0.25f), Quaternion.Identity);
        AssertAt(set.Shapes[1], new(0, 0, 0.5f), Quaternion.Identity);
        Assert.Equal((PoseProvenance.MotionTableSource, 0x09003500u, "setup", 0x03003500u), (set.Pose.Source, set.Pose.MotionTableId, set.Pose.MotionTableFrom, set.Pose.AnimationId));
        Assert.Contains(set.Diagnostics, d => d.Code == PoseDiagnosticCodes.AnimationParts && d.Message.Contains("1 of the Setup's 2 parts"));
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
        Assert.Equal([0x020019FFu, 0x02003500u, 0x02003600u], report.Rows.Select(r => r.SetupId));
        Assert.Equal(["motion-table", "motion-table", "default-animation"], report.Rows.Select(r => r.PoseSource));
    }

    [Fact]
    public void Each_motion_table_and_animation_is_decoded_once_however_many_setups_share_it()
    {
        using var portal = SampleDat.OpenPortal();
        var engine = new ExportEngine(portal, new ShapeBuildOptions(ShapePolicy.Retail));
        foreach (var id in portal.ListIds(DatObjectKind.Setup)) engine.ExportSetup(id);
        var distinct = portal.MotionObjectsDecoded;
        // Read: the three tables (0x09000016 serves two doors), the closed door frame 0x03000100, 0x03003500, and
        // 0x03003600 (the DefaultAnimation of two Setups). Never needed closed: the open, swing and unreachable animations.
        Assert.Equal(6, distinct);
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
        Assert.Equal(6, source.MotionObjectsDecoded);
    }
}
