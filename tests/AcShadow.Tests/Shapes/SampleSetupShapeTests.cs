using AcShadow.Core.Dat;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Shapes;

/// <summary>Every Setup of the forged sample, read from the dat, under both policies.</summary>
public class SampleSetupShapeTests
{
    // setup, policy, expected collision types in order, placement used, diagnostic codes that must appear
    public static TheoryData<uint, string, string, string, string> Cases => new()
    {
        { 0x020019FF, "retail", "bsp bsp bsp", "Resting", "pose-moved" },
        { 0x020019FF, "union", "cylinder bsp bsp bsp", "Resting", "pose-moved" },
        { 0x0200024F, "retail", "bsp", "Resting", "no-default-state door-motion" },
        { 0x0200024F, "union", "cylinder bsp", "Resting", "no-default-state door-motion" },
        { 0x02000281, "retail", "bsp bsp bsp bsp", "Resting", "no-default-state door-motion" },
        { 0x02000281, "union", "cylinder bsp bsp bsp bsp", "Resting", "no-default-state door-motion" },
        { 0x02000311, "retail", "bsp", "Resting", "pose-moved" },
        { 0x02000311, "union", "cylinder bsp", "Resting", "pose-moved" },
        { 0x02001000, "retail", "cylinder cylinder", "Resting", "" },
        { 0x02001000, "union", "cylinder cylinder", "Resting", "" },
        { 0x02001100, "retail", "sphere sphere", "Resting", "" },
        { 0x02001100, "union", "cylinder cylinder", "Resting", "" },
        { 0x02002000, "retail", "sphere", "Default", "" },
        { 0x02002000, "union", "cylinder", "Default", "" },
        { 0x02003000, "retail", "bsp bsp bsp", "Resting", "flag-mismatch non-uniform-scale" },
        { 0x02003000, "union", "bsp bsp bsp", "Resting", "flag-mismatch" },
        { 0x02003100, "retail", "sphere", "Default", "flag-mismatch" },
        { 0x02003100, "union", "cylinder", "Default", "flag-mismatch" },
        { 0x02003200, "retail", "", "None", "no-pose no-shapes" },
        { 0x02003200, "union", "bsp bsp", "Other", "" },
        { 0x02003300, "retail", "bsp", "None", "" },
        { 0x02003300, "union", "bsp", "None", "" },
        { 0x02003400, "retail", "bsp", "Resting", "missing-gfxobj" },
        { 0x02003400, "union", "bsp", "Resting", "missing-gfxobj" },
        { 0x02003500, "retail", "bsp bsp", "Resting", "animation-parts pose-moved" },
        { 0x02003500, "union", "bsp bsp", "Resting", "animation-parts pose-moved" },
        { 0x02003600, "retail", "bsp", "Resting", "pose-moved" },
        { 0x02003600, "union", "bsp", "Resting", "pose-moved" },
        { 0x02003700, "retail", "bsp", "Resting", "pose-moved" },
        { 0x02003700, "union", "bsp", "Resting", "pose-moved" },
        { 0x02003800, "retail", "bsp", "Resting", "missing-animation pose-moved" },
        { 0x02003800, "union", "bsp", "Resting", "missing-animation pose-moved" },
        { 0x02003900, "retail", "bsp bsp bsp", "Resting", "animation-parts pose-moved" },
        { 0x02003900, "union", "bsp bsp bsp", "Resting", "animation-parts pose-moved" },
        { 0x02005000, "retail", "bsp", "Default", "" },
        { 0x02005000, "union", "bsp", "Default", "" },
        { 0x02006000, "retail", "bsp", "Resting", "" },
        { 0x02006000, "union", "bsp", "Resting", "" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Sample_setup_builds_the_expected_shapes(uint setupId, string policy, string types, string placement, string codes)
    {
        using var dat = SampleDat.OpenPortal();
        ShapePolicies.TryParse(policy, out var p);
        var setup = dat.ReadSetup(setupId)!;
        var set = ShadowShapeBuilder.Build(setup, dat.ReadGfxObj, new ShapeBuildOptions(p), dat);
        Assert.Equal(types, string.Join(' ', set.Shapes.Select(s => s.CollisionType.ToString().ToLowerInvariant())));
        Assert.Equal(placement, set.Placement.Used);
        foreach (var code in codes.Split(' ', StringSplitOptions.RemoveEmptyEntries))
            Assert.Contains(set.Diagnostics, d => d.Code == code);
        if (codes.Length == 0) Assert.Empty(set.Diagnostics);
    }

    [Fact]
    public void Every_sample_setup_is_covered()
    {
        using var dat = SampleDat.OpenPortal();
        var covered = Cases.Select(c => (uint)c[0]).ToHashSet();
        Assert.Equal(dat.ListIds(DatObjectKind.Setup).Order(), covered.Order());
    }

    [Fact]
    public void Door_parts_are_posed_by_resting_with_the_second_jamb_mirrored()
    {
        using var dat = SampleDat.OpenPortal();
        var set = ShadowShapeBuilder.Build(dat.ReadSetup(0x020019FF)!, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail));
        var resting = dat.ReadSetup(0x020019FF)!.FindPlacement(0x65)!;
        for (var i = 0; i < 3; i++)
        {
            Assert.Equal(resting.Frames[i].Position, set.Shapes[i].LocalPosition);
            Assert.Equal(resting.Frames[i].Rotation, set.Shapes[i].LocalRotation);
        }
        Assert.Equal(1f, MathF.Abs(set.Shapes[2].LocalRotation.Z), 5);
    }

    [Fact]
    public void Default_scale_z_sets_each_part_scale_under_retail_only()
    {
        using var dat = SampleDat.OpenPortal();
        var setup = dat.ReadSetup(0x02003000)!;
        var retail = ShadowShapeBuilder.Build(setup, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail, 2f));
        Assert.Equal(setup.DefaultScale.Select(s => s.Z * 2f), retail.Shapes.Select(s => s.Scale));
        var gfx = dat.ReadGfxObj(setup.Parts[0])!;
        Assert.Equal(gfx.PhysicsBsp!.BoundingSphere.Radius * setup.DefaultScale[0].Z * 2f, retail.Shapes[0].Radius);
        Assert.Equal(setup.FindPlacement(0x65)!.Frames[1].Position * 2f, retail.Shapes[1].LocalPosition);
        var union = ShadowShapeBuilder.Build(setup, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Union, 2f));
        Assert.All(union.Shapes, s => Assert.Equal(2f, s.Scale));
    }

    [Fact]
    public void Door_sphere_becomes_a_two_r_cylinder_under_union()
    {
        using var dat = SampleDat.OpenPortal();
        var set = ShadowShapeBuilder.Build(dat.ReadSetup(0x020019FF)!, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Union));
        var cyl = set.Shapes[0];
        Assert.Equal(ShapeSource.Sphere, cyl.Source);
        Assert.Equal(0.1f, cyl.Radius);
        Assert.Equal(0.2f, cyl.CylHeight);
        Assert.Equal(0.018f, cyl.LocalPosition.Z);
    }
}
