using AcShadow.Core.Catalog;
using AcShadow.Core.Dat;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Tests.Forge;

[Trait("Speed", "Slow")]
public sealed class DeterminismAndScaleTests(SmallScaleFixture fixture) : IClassFixture<SmallScaleFixture>
{
    [Fact]
    public void Building_the_sample_twice_gives_identical_bytes()
    {
        var a = SpecCompiler.Compile(SampleDats.Spec);
        var b = SpecCompiler.Compile(SpecJson.Parse(SampleDats.Json));
        Assert.Equal(a.Portal, b.Portal);
        Assert.Equal(a.Cell, b.Cell);
    }

    [Fact]
    public void A_scale_spec_is_a_function_of_count_and_seed()
    {
        var a = SpecCompiler.Compile(ScaleSpecGenerator.Generate(40, 3));
        var b = SpecCompiler.Compile(ScaleSpecGenerator.Generate(40, 3));
        var c = SpecCompiler.Compile(ScaleSpecGenerator.Generate(40, 4));
        Assert.Equal(a.Portal, b.Portal);
        Assert.Equal(a.Cell, b.Cell);
        Assert.NotEqual(a.Portal, c.Portal);
    }

    [Fact]
    public void Every_physics_gfxobj_of_a_small_scale_spec_has_a_sound_bsp()
    {
        var portal = fixture.Files.Portal;
        var checkedCount = 0;
        foreach (var id in portal.ListIds(DatObjectKind.GfxObj))
        {
            var gfx = portal.ReadGfxObj(id)!;
            if (!gfx.HasPhysics) continue;
            Assert.Equal([], BspInvariants.Check(gfx).Select(p => $"0x{id:X8}: {p}"));
            Assert.InRange(gfx.PhysicsPolygons.Count, ScaleSpecGenerator.MinPhysicsPolygons, ScaleSpecGenerator.MaxPhysicsPolygons);
            checkedCount++;
        }
        Assert.True(checkedCount > 100, $"{checkedCount} physics GfxObjs");
    }

    [Fact]
    public void Every_door_setup_id_is_a_three_part_door_in_the_scale_dat()
    {
        var portal = fixture.Files.Portal;
        Assert.All(DoorCatalog.SetupIds, id =>
        {
            var door = portal.ReadSetup(id);
            Assert.NotNull(door);
            Assert.Equal(3, door!.Parts.Count);
            Assert.Equal(door.Parts[1], door.Parts[2]);
            Assert.True(door.Flags.HasFlag(Core.Dat.Objects.SetupFlags.HasPhysicsBsp));
        });
    }

    [Fact]
    public void The_scale_dat_mixes_statics_creatures_and_items()
    {
        var portal = fixture.Files.Portal;
        var setups = portal.ListIds(DatObjectKind.Setup).Select(id => portal.ReadSetup(id)!).ToArray();
        Assert.Equal(SmallScaleFixture.Setups, setups.Length);
        Assert.Contains(setups, s => s.CylSpheres.Count > 0 && s.Parts.All(p => !portal.ReadGfxObj(p)!.HasPhysics));
        Assert.Contains(setups, s => s.Spheres.Count > 0 && s.CylSpheres.Count == 0 && s.Parts.Count == 1 && !DoorCatalog.SetupIds.Contains(s.Id));
        Assert.Contains(setups, s => s.Parts.Count >= 4 && s.Parts.All(p => portal.ReadGfxObj(p)!.HasPhysics));
        Assert.NotNull(fixture.Files.Cell);
    }

    [Fact]
    public void The_door_id_list_matches_the_shared_domain_notes_when_they_are_present()
    {
        var tsv = FindUp(Path.Combine("shared", "domain", "door-setups.tsv"));
        if (tsv is null) return; // the notes live beside the repo, not in it
        var ids = File.ReadLines(tsv).Where(l => l.StartsWith("0x", StringComparison.Ordinal))
            .Select(l => Convert.ToUInt32(l.Split('\t')[0], 16)).ToArray();
        Assert.Equal(ids, DoorCatalog.SetupIds);
    }

    private static string? FindUp(string relative)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, relative);
            if (File.Exists(candidate)) return candidate;
        }
        return File.Exists(Path.Combine("/work", relative)) ? Path.Combine("/work", relative) : null;
    }
}
