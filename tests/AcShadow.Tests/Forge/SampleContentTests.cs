using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Catalog;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forge;
using AcShadow.Forging;
using static AcShadow.Forge.SampleSpecAuthor;

namespace AcShadow.Tests.Forge;

/// <summary>The built-in sample, read back from the files `forge sample` wrote, holds every required case.</summary>
public sealed class SampleContentTests(SampleFixture fixture) : IClassFixture<SampleFixture>
{
    private readonly DatDatabase _portal = fixture.Files.Portal;

    private Setup Setup(uint id) => _portal.ReadSetup(id) ?? throw new Xunit.Sdk.XunitException($"Setup 0x{id:X8} is not in the sample dat");
    private GfxObj Gfx(uint id) => _portal.ReadGfxObj(id) ?? throw new Xunit.Sdk.XunitException($"GfxObj 0x{id:X8} is not in the sample dat");

    private static Vector3 Place(Frame frame, Vector3 local) => Vector3.Transform(local, frame.Rotation) + frame.Position;

    [Fact]
    public void Door_0x020019FF_has_the_retail_parts_sphere_and_soda_can_size()
    {
        var door = Setup(DoorSetup);
        Assert.Equal([DoorLeaf, DoorJamb, DoorJamb], door.Parts);
        Assert.Empty(door.CylSpheres);
        var sphere = Assert.Single(door.Spheres);
        Assert.Equal(0.1f, sphere.Radius);
        Assert.Equal(new Vector3(0, 0, 0.018f), sphere.Center);
        Assert.Equal(0.141f, door.Radius);
        Assert.Equal(0.2f, door.Height);
        Assert.True(door.Flags.HasFlag(SetupFlags.HasPhysicsBsp));
        Assert.Contains(DoorSetup, DoorCatalog.SetupIds);
    }

    [Fact]
    public void Door_resting_and_default_differ_and_the_second_jamb_is_mirrored_180_about_z()
    {
        var door = Setup(DoorSetup);
        var resting = door.FindPlacement(Placement.Resting)!;
        var @default = door.FindPlacement(Placement.Default)!;
        Assert.Equal(3, resting.Frames.Count);
        Assert.NotEqual(resting.Frames[0], @default.Frames[0]);
        foreach (var p in new[] { resting, @default })
        {
            Assert.Equal(Quaternion.Identity, p.Frames[1].Rotation);
            Assert.Equal(new Quaternion(0, 0, 1, 0), p.Frames[2].Rotation); // stored w=0, x=0, y=0, z=1
        }
    }

    [Fact]
    public void Door_leaf_is_a_closed_box_of_about_1_93_by_0_26_by_2_2()
    {
        var leaf = Gfx(DoorLeaf);
        Assert.True(leaf.HasPhysics);
        Assert.Equal(6, leaf.PhysicsPolygons.Count);
        var min = leaf.Vertices.Values.Aggregate(Vector3.Min);
        var max = leaf.Vertices.Values.Aggregate(Vector3.Max);
        var size = max - min;
        Assert.Equal(1.93, size.X, 4);
        Assert.Equal(0.26, size.Y, 4);
        Assert.Equal(2.2, size.Z, 4);
    }

    [Fact]
    public void Each_placed_jamb_threshold_spans_the_whole_doorway()
    {
        var jamb = Gfx(DoorJamb);
        var threshold = jamb.PhysicsPolygons.Single(p => p.Value.VertexIds.All(v => jamb.Vertices[(ushort)v].Y == 0)).Value;
        var points = threshold.VertexIds.Select(v => jamb.Vertices[(ushort)v]).ToArray();
        Assert.InRange(points.Max(p => p.Z), 0.25f, 0.35f);
        var resting = Setup(DoorSetup).FindPlacement(Placement.Resting)!;
        foreach (var frame in new[] { resting.Frames[1], resting.Frames[2] })
        {
            var world = points.Select(p => Place(frame, p)).ToArray();
            Assert.True(world.Min(p => p.X) <= -0.965f + 1e-4f && world.Max(p => p.X) >= 0.965f - 1e-4f,
                $"threshold placed at {frame.Position} covers x {world.Min(p => p.X)}..{world.Max(p => p.X)}, not the 2 m doorway");
            Assert.All(world, p => Assert.True(MathF.Abs(p.Y) < 1e-5f));
        }
    }

    [Fact]
    public void Two_more_door_setups_from_the_ace_door_list_have_other_layouts()
    {
        var single = Setup(SinglePartDoorSetup);
        var @double = Setup(DoubleDoorSetup);
        Assert.Single(single.Parts);
        Assert.True(Gfx(single.Parts[0]).HasPhysics);
        Assert.Equal(4, @double.Parts.Count);
        Assert.Equal(@double.Parts[0], @double.Parts[1]);
        Assert.Contains(SinglePartDoorSetup, DoorCatalog.SetupIds);
        Assert.Contains(DoubleDoorSetup, DoorCatalog.SetupIds);
        Assert.NotEqual(@double.FindPlacement(Placement.Resting)!.Frames, @double.FindPlacement(Placement.Default)!.Frames);
    }

    [Fact]
    public void Creature_has_cylspheres_and_drawing_only_parts()
    {
        var creature = Setup(CreatureSetup);
        Assert.Equal(2, creature.CylSpheres.Count);
        Assert.Contains(creature.CylSpheres, c => c.Radius == 0.35f && c.Height == 1.8f);
        Assert.All(creature.Parts, id =>
        {
            var part = Gfx(id);
            Assert.False(part.HasPhysics);
            Assert.True(part.Flags.HasFlag(GfxObjFlags.HasDrawing));
        });
    }

    [Fact]
    public void Item_has_spheres_only_and_one_drawing_only_part()
    {
        var item = Setup(ItemSetup);
        Assert.Empty(item.CylSpheres);
        Assert.NotEmpty(item.Spheres);
        Assert.False(Gfx(Assert.Single(item.Parts)).HasPhysics);
    }

    [Fact]
    public void Multi_part_static_has_rotated_scaled_physics_parts_but_no_physics_flag()
    {
        var s = Setup(StaticSetup);
        Assert.True(s.Parts.Count >= 3);
        Assert.All(s.Parts, id => Assert.True(Gfx(id).HasPhysics));
        Assert.False(s.Flags.HasFlag(SetupFlags.HasPhysicsBsp));
        Assert.True(s.Flags.HasFlag(SetupFlags.HasDefaultScale));
        Assert.Equal(s.Parts.Count, s.DefaultScale.Count);
        Assert.Contains(s.DefaultScale, v => v.X != v.Z);
        Assert.Contains(s.DefaultScale, v => v.Z == 1.5f);
        Assert.True(s.FindPlacement(Placement.Resting)!.Frames.Count(f => f.Rotation != Quaternion.Identity) >= 2);
    }

    [Fact]
    public void A_setup_sets_the_physics_flag_though_no_part_has_physics()
    {
        var s = Setup(FlagWithoutBspSetup);
        Assert.True(s.Flags.HasFlag(SetupFlags.HasPhysicsBsp));
        Assert.All(s.Parts, id => Assert.False(Gfx(id).HasPhysics));
    }

    [Fact]
    public void A_multi_part_physics_setup_has_only_an_Other_placement()
    {
        var s = Setup(OtherOnlySetup);
        Assert.True(s.Parts.Count >= 2);
        Assert.All(s.Parts, id => Assert.True(Gfx(id).HasPhysics));
        Assert.Equal(0x66u, Assert.Single(s.PlacementFrames).Placement);
        Assert.Null(s.FindPlacement(Placement.Resting));
        Assert.Null(s.FindPlacement(Placement.Default));
    }

    [Fact]
    public void A_single_physics_part_setup_has_no_placement_frames()
    {
        var s = Setup(NoPlacementSetup);
        Assert.True(Gfx(Assert.Single(s.Parts)).HasPhysics);
        Assert.Empty(s.PlacementFrames);
    }

    [Fact]
    public void A_setup_names_a_part_the_dat_does_not_hold()
    {
        var s = Setup(MissingPartSetup);
        Assert.Contains(MissingPart, s.Parts);
        Assert.Null(_portal.ReadGfxObj(MissingPart));
        Assert.NotNull(_portal.ReadGfxObj(s.Parts.Single(p => p != MissingPart)));
    }

    [Fact]
    public void The_house_has_at_least_200_physics_polygons_and_a_deep_bsp()
    {
        var house = Gfx(House);
        Assert.True(house.PhysicsPolygons.Count >= 200, $"{house.PhysicsPolygons.Count} polygons");
        Assert.InRange(BspInvariants.Depth(house.PhysicsBsp!), 6, 64);
        Assert.True(BspInvariants.Leaves(house.PhysicsBsp!).Count() >= 20);
        Assert.Equal([House], Setup(BuildingSetup).Parts);
    }

    [Fact]
    public void A_drawing_only_gfxobj_has_no_physics_but_drawing()
    {
        var gem = Gfx(ItemGem);
        Assert.Equal(GfxObjFlags.HasDrawing, gem.Flags);
        Assert.Empty(gem.PhysicsPolygons);
        Assert.Null(gem.PhysicsBsp);
    }

    [Fact]
    public void The_odd_gfxobj_has_a_degenerate_and_a_non_planar_polygon_and_still_a_bsp()
    {
        var odd = Gfx(OddGfxObj);
        var dump = BspExtractor.Extract(odd)!;
        Assert.Single(dump.Stats.DegeneratePolygons);
        Assert.Single(dump.Stats.NonPlanarPolygons);
        Assert.Empty(BspInvariants.Check(odd));
        var planes = odd.PhysicsPolygons.Select(p => PolygonPlane.Compute(p.Value.VertexIds.Select(v => odd.Vertices[(ushort)v]).ToArray())).ToArray();
        Assert.Single(planes, p => p is null);
    }

    [Fact]
    public void The_landblock_places_door_bare_gfxobj_static_and_building_rotated_about_z()
    {
        var info = fixture.Files.Cell!.ReadLandBlockInfo(Landblock)!;
        Assert.Contains(info.Objects, o => o.Id == DoorSetup);
        Assert.Contains(info.Objects, o => o.Id == StaticSetup);
        Assert.Contains(info.Objects, o => DatObjectKind.GfxObj.Contains(o.Id) && _portal.ReadGfxObj(o.Id)!.HasPhysics);
        Assert.All(info.Objects, o =>
        {
            Assert.Equal(0f, o.Frame.Rotation.X);
            Assert.Equal(0f, o.Frame.Rotation.Y);
            Assert.NotEqual(0f, o.Frame.Rotation.Z);
        });
        var building = Assert.Single(info.Buildings);
        Assert.Equal(House, building.ModelId);
        Assert.NotEqual(Quaternion.Identity, building.Frame.Rotation);
    }

    [Fact]
    public void The_sample_stays_small()
    {
        var ids = _portal.ListIds(DatObjectKind.GfxObj).Count + _portal.ListIds(DatObjectKind.Setup).Count;
        Assert.InRange(ids, 20, 60);
    }

    [Fact]
    public void Every_physics_gfxobj_of_the_sample_has_a_sound_bsp()
    {
        var checkedCount = 0;
        foreach (var id in _portal.ListIds(DatObjectKind.GfxObj))
        {
            var gfx = _portal.ReadGfxObj(id)!;
            if (!gfx.HasPhysics) continue;
            Assert.Equal([], BspInvariants.Check(gfx).Select(p => $"0x{id:X8}: {p}"));
            checkedCount++;
        }
        Assert.True(checkedCount >= 10);
    }

    [Fact]
    public void In_memory_sample_equals_the_files_forge_sample_wrote()
    {
        var (portal, cell) = SampleDats.Build();
        Assert.Equal(portal, File.ReadAllBytes(Path.Combine(fixture.Files.Directory, ForgeApp.PortalFileName)));
        Assert.Equal(cell, File.ReadAllBytes(Path.Combine(fixture.Files.Directory, ForgeApp.CellFileName)));
    }

    [Fact]
    public void Embedded_sample_json_is_what_the_author_code_writes()
    {
        // Sample/sample.json is regenerated with `forge sample --write-spec`; this keeps it in step.
        Assert.Equal(AcShadow.Forging.Spec.SpecJson.Serialize(SampleSpecAuthor.Create()), SampleDats.Json);
    }
}
