using AcShadow.Forge;
using System.Numerics;
using AcShadow.Analysis.Doctor;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Doctor;

/// <summary>
/// The doctor on the forged sample, and on copies of it each built to break one check: the matching check
/// says "differs" and names the object, and the checks the change does not touch keep their verdict.
/// </summary>
public sealed class DoctorReportTests
{
    /// <summary>
    /// The sample forges the divergences the tool exposes on purpose (SampleSpecAuthor): a static whose
    /// flag is clear though its parts have BSPs, a Setup flagged with no BSP part, one placed only by
    /// Other, and non-uniform DefaultScale. Those checks differ, naming exactly those Setups.
    /// </summary>
    private static readonly Dictionary<string, uint[]> SampleDivergences = new()
    {
        ["setup.physics-bsp-flag"] = [SampleSpecAuthor.StaticSetup, SampleSpecAuthor.FlagWithoutBspSetup],
        ["setup.placements"] = [SampleSpecAuthor.OtherOnlySetup],
        ["setup.default-scale"] = [SampleSpecAuthor.StaticSetup],
        ["setup.parts-posed"] = [SampleSpecAuthor.OtherOnlySetup],
        // The door catalog gives both doors a table without its default cycle: they keep their placement pose.
        ["setup.motion-pose"] = [SampleSpecAuthor.SinglePartDoorSetup, SampleSpecAuthor.DoubleDoorSetup],
    };

    [Fact]
    public void On_the_sample_every_check_holds_but_the_divergences_the_sample_forges_on_purpose()
    {
        var report = DoctorDats.Report(DoctorDats.Portal(DoctorDats.SampleObjects()));
        foreach (var check in report.Checks)
        {
            if (SampleDivergences.TryGetValue(check.Key, out var ids))
            {
                Assert.Equal(DoctorVerdict.Differs, check.Verdict);
                Assert.Equal(ids.Order(), check.Examples);
            }
            else if (check.Key is "tool.determinism") Assert.Equal(DoctorVerdict.NotChecked, check.Verdict);
            else Assert.True(check.Verdict == DoctorVerdict.Holds, $"{check.Key}: {check.Verdict.Text()} ({check.Headline})");
        }
        var planes = report.Check("bsp.planes");
        Assert.True(Count(planes, "internalNodes") > 0);
        Assert.Equal(Count(planes, "internalNodes"), Count(planes, "reproduced"));
        Assert.Equal(SampleDat.OpenPortal().ListIds(DatObjectKind.Setup).Count, Count(report.Check("reading.decode"), "setupsRead"));

        // From the sample spec: the door's closed cycle, the animated static's table and the DefaultAnimation
        // column each move a part, and so do the four pose-rule Setups (0x02000311, 0x02003700-0x02003900; the
        // absent animation of 0x02003800 is dropped, not a fallback); the two doors on the broken table fall back.
        var pose = report.Check("setup.motion-pose");
        Assert.Equal(7, Count(pose, "poseDiffersFromPlacement"));
        Assert.Equal(2, Count(pose, "fellBackToPlacement"));
        Assert.Equal(Count(pose, "setupsWithMotion"), Count(pose, "motionPosed") + Count(pose, "fellBackToPlacement"));
    }

    [Fact]
    public void A_plane_nudged_by_one_ulp_is_not_reproduced_and_its_gfxobj_is_named()
    {
        var objects = DoctorDats.SampleObjects();
        var gfx = DoctorDats.BspGfxObjs(objects).First();
        var root = gfx.PhysicsBsp!;
        var nudged = root with { SplittingPlane = new Plane(root.SplittingPlane.Normal, MathF.BitIncrement(root.SplittingPlane.D)) };
        objects[gfx.Id] = DoctorDats.Encode((gfx with { PhysicsBsp = nudged }).Write);

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("bsp.planes");

        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Equal([gfx.Id], check.Examples);
        Assert.Equal(1, Count(check, "notReproduced"));
        Assert.Equal(1, check.Histogram!.Single(b => b.Key == "1").Value);
        Assert.Equal(1, check.Histogram!.Sum(b => b.Value));
    }

    [Fact]
    public void A_one_child_node_is_counted_and_its_gfxobj_is_named()
    {
        var objects = DoctorDats.SampleObjects();
        var before = DoctorDats.Report(DoctorDats.Portal(objects)).Check("bsp.both-children");
        var gfx = DoctorDats.BspGfxObjs(objects).First(g => g.PhysicsBsp!.Type == BspNodeType.BPIN);
        var root = gfx.PhysicsBsp!;
        objects[gfx.Id] = DoctorDats.Encode((gfx with { PhysicsBsp = root with { Type = BspNodeType.BPIn, Neg = null } }).Write);

        var after = DoctorDats.Report(DoctorDats.Portal(objects)).Check("bsp.both-children");

        Assert.Equal(DoctorVerdict.Differs, after.Verdict);
        Assert.Contains(gfx.Id, after.Examples);
        Assert.Equal(Count(before, "oneChild") + 1 - OneChildNodesRemoved(root.Neg!), Count(after, "oneChild"));
    }

    [Fact]
    public void A_flag_that_disagrees_with_the_parts_names_the_setup()
    {
        var objects = DoctorDats.SampleObjects();
        var door = DoctorDats.ReadSetup(objects, 0x020019FF);
        Assert.True(door.Flags.HasFlag(SetupFlags.HasPhysicsBsp));
        objects[door.Id] = DoctorDats.Encode((door with { Flags = door.Flags & ~SetupFlags.HasPhysicsBsp }).Write);

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("setup.physics-bsp-flag");

        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Equal(SampleDivergences["setup.physics-bsp-flag"].Append(door.Id).Order(), check.Examples);
        Assert.Equal(2, Count(check, "bspPartsWithoutFlag"));
    }

    [Fact]
    public void An_unknown_hook_type_in_a_placement_frame_names_the_setup_it_loses()
    {
        var objects = DoctorDats.SampleObjects();
        var door = DoctorDats.ReadSetup(objects, 0x020019FF);
        // A NoOp hook (type 0, no payload) with a direction no other field holds, then its type changed to one no reader knows.
        const int direction = 0x5EADBEEF;
        var placement = door.PlacementFrames[0] with { Hooks = [new AnimationHook(AnimationHookType.NoOp, direction, [])] };
        var bytes = DoctorDats.Encode((door with { PlacementFrames = [placement, .. door.PlacementFrames.Skip(1)] }).Write);
        byte[] hook = [1, 0, 0, 0, 0, 0, 0, 0, .. BitConverter.GetBytes(direction)];
        var at = bytes.AsSpan().IndexOf(hook);
        Assert.True(at > 0 && bytes.AsSpan(at + 1).IndexOf(hook) < 0);
        bytes[at + 4] = 0x63;
        objects[door.Id] = bytes;

        var report = DoctorDats.Report(DoctorDats.Portal(objects));

        var hooks = report.Check("reading.hooks");
        Assert.Equal(DoctorVerdict.Differs, hooks.Verdict);
        Assert.Equal([door.Id], hooks.Examples);
        var decode = report.Check("reading.decode");
        Assert.Equal(DoctorVerdict.Differs, decode.Verdict);
        Assert.Equal([door.Id], decode.Examples);
        Assert.Equal([new KeyValuePair<string, long>(DecodeFailureReason.UnknownHookType, 1)], decode.Histogram);
    }

    [Fact]
    public void Known_hook_types_are_counted_by_type()
    {
        var objects = DoctorDats.SampleObjects();
        var before = DoctorDats.Report(DoctorDats.Portal(objects)).Check("reading.hooks").Histogram!.ToDictionary();
        var door = DoctorDats.ReadSetup(objects, 0x020019FF);
        var placement = door.PlacementFrames[0] with
        {
            Hooks = [new AnimationHook(AnimationHookType.Sound, 1, new byte[4]), new AnimationHook(AnimationHookType.Sound, 1, new byte[4]), new AnimationHook(AnimationHookType.NoDraw, 0, new byte[4])],
        };
        objects[door.Id] = DoctorDats.Encode((door with { PlacementFrames = [placement, .. door.PlacementFrames.Skip(1)] }).Write);

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("reading.hooks");

        Assert.Equal(DoctorVerdict.Holds, check.Verdict);
        var added = check.Histogram!.Select(h => (h.Key, h.Value - before.GetValueOrDefault(h.Key))).Where(h => h.Item2 != 0);
        Assert.Equal([("Sound", 2L), ("NoDraw", 1L)], added);
    }

    [Fact]
    public void A_directory_written_as_DatReaderWriter_writes_it_differs_from_retail_style()
    {
        var objects = DoctorDats.SampleObjects();
        var report = DoctorDats.Report(DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, Fill: BranchFill.Cdcd)));

        var check = report.Check("reading.directory");
        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Contains("0xCDCDCDCD", check.Headline);
        Assert.Equal(1, check.Histogram!.Single(h => h.Key == nameof(BranchFill.Cdcd)).Value);
        // Everything else reads as from the retail-style copy.
        Assert.Equal(DoctorVerdict.Holds, report.Check("reading.decode").Verdict);
        Assert.Equal(DoctorVerdict.Holds, DoctorDats.Report(DoctorDats.Portal(objects)).Check("reading.directory").Verdict);
    }

    [Fact]
    public void A_dat_without_its_iteration_record_differs()
    {
        var objects = DoctorDats.SampleObjects();
        Assert.True(objects.Remove(IterationRecord.Id));

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("reading.iteration");

        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Equal(1, Count(check, "filesWithoutReadableRecord"));
    }

    [Fact]
    public void Bytes_left_over_after_a_setup_name_it()
    {
        var objects = DoctorDats.SampleObjects();
        objects[0x020019FF] = [.. objects[0x020019FF], 0, 0, 0, 0];

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("reading.bytes-used");

        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Equal([0x020019FFu], check.Examples);
    }

    [Fact]
    public void A_bounding_sphere_too_small_for_its_polygons_names_the_gfxobj()
    {
        var objects = DoctorDats.SampleObjects();
        var gfx = DoctorDats.BspGfxObjs(objects).First();
        var root = gfx.PhysicsBsp!;
        var shrunk = root with { BoundingSphere = root.BoundingSphere with { Radius = root.BoundingSphere.Radius * 0.5f } };
        objects[gfx.Id] = DoctorDats.Encode((gfx with { PhysicsBsp = shrunk }).Write);

        var check = DoctorDats.Report(DoctorDats.Portal(objects)).Check("bsp.bounding-spheres");

        Assert.Equal(DoctorVerdict.Differs, check.Verdict);
        Assert.Equal([gfx.Id], check.Examples);
        Assert.Equal(1, Count(check, "tooSmall"));
        Assert.True(Count(check, "maxExcessNanometres") > 100_000);
    }

    [Fact]
    public void A_solid_leaf_without_polygons_and_a_leaf_naming_a_missing_polygon_name_their_gfxobjs()
    {
        var objects = DoctorDats.SampleObjects();
        var gfxObjs = DoctorDats.BspGfxObjs(objects).Take(2).ToArray();
        objects[gfxObjs[0].Id] = DoctorDats.Encode((gfxObjs[0] with { PhysicsBsp = ReplaceFirstLeaf(gfxObjs[0].PhysicsBsp!, l => l with { Solid = 1, Polygons = [] }) }).Write);
        objects[gfxObjs[1].Id] = DoctorDats.Encode((gfxObjs[1] with { PhysicsBsp = ReplaceFirstLeaf(gfxObjs[1].PhysicsBsp!, l => l with { Polygons = [.. l.Polygons, 0xFFF0] }) }).Write);

        var report = DoctorDats.Report(DoctorDats.Portal(objects));

        Assert.Equal([gfxObjs[0].Id], report.Check("bsp.solid-leaves").Examples);
        Assert.Equal(DoctorVerdict.Differs, report.Check("bsp.solid-leaves").Verdict);
        Assert.Equal([gfxObjs[1].Id], report.Check("bsp.leaf-polygons").Examples);
        Assert.Equal(DoctorVerdict.Differs, report.Check("bsp.leaf-polygons").Verdict);
    }

    [Fact]
    public void Checks_with_nothing_to_check_are_not_applicable()
    {
        var objects = DoctorDats.SampleObjects().Where(o => !DatObjectKind.GfxObj.Contains(o.Key)).ToDictionary();

        var report = DoctorDats.Report(DoctorDats.Portal(objects));

        foreach (var key in new[] { "bsp.planes", "bsp.both-children", "bsp.solid-leaves", "bsp.leaf-polygons", "bsp.bounding-spheres" })
            Assert.Equal(DoctorVerdict.NotApplicable, report.Check(key).Verdict);
        Assert.Equal(DoctorVerdict.Holds, report.Check("reading.decode").Verdict);
    }

    [Fact]
    public void Examples_are_the_smallest_twenty_ids_whatever_the_thread_count()
    {
        var objects = DoctorDats.SampleObjects();
        var door = DoctorDats.ReadSetup(objects, 0x020019FF);
        // 30 copies of the door with the flag cleared: 30 disagreements, 20 examples.
        for (uint i = 0; i < 30; i++)
            objects[0x02005000 + i * 7] = DoctorDats.Encode((door with { Id = 0x02005000 + i * 7, Flags = SetupFlags.None }).Write);
        var portal = DoctorDats.Portal(objects);

        var one = DoctorDats.Report(portal, jobs: 1).Check("setup.physics-bsp-flag");
        var four = DoctorDats.Report(portal, jobs: 4).Check("setup.physics-bsp-flag");

        Assert.Equal(Finding.MaxExamples, one.Examples.Count);
        Assert.Equal(one.Examples, four.Examples);
        Assert.Equal(one.Examples.Order(), one.Examples);
        Assert.Equal(32, Count(one, "bspPartsWithoutFlag") + Count(one, "flagWithoutBspParts"));
    }

    private static long Count(DoctorCheck check, string name) => check.Counts.Single(c => c.Key == name).Value;

    private static int OneChildNodesRemoved(PhysicsBspNode removed) =>
        DoctorDats.Nodes(removed).Count(n => !n.IsLeaf && (n.Pos is null || n.Neg is null));

    private static PhysicsBspNode ReplaceFirstLeaf(PhysicsBspNode node, Func<PhysicsBspNode, PhysicsBspNode> change)
    {
        if (node.IsLeaf) return change(node);
        return node.Pos is { } pos ? node with { Pos = ReplaceFirstLeaf(pos, change) } : node with { Neg = ReplaceFirstLeaf(node.Neg!, change) };
    }
}
