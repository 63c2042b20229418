using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;
using static AcShadow.Tests.Support.Records;

namespace AcShadow.Tests.Shapes;

/// <summary>Builder rules on in-memory records, for cases a dat file cannot hold.</summary>
public class ShadowShapeBuilderRecordTests
{
    private static readonly GfxObj A = BoxGfxObj(0x01000001);
    private static readonly GfxObj B = BoxGfxObj(0x01000002);

    [Fact]
    public void Retail_skips_parts_beyond_a_short_placement_frame_and_says_so()
    {
        // Retail poses min(NumParts, frames) parts (CPartArray::UpdateParts). A dat always stores one
        // frame per part, so this case only arises from in-memory data.
        var setup = Setup(0x02000001, [A.Id, B.Id, A.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(2, 0, 0))]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Retail));
        Assert.Equal([0, 1], set.Shapes.Select(s => s.SourceIndex));
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.NoPose && d.Message.Contains("part 2"));
    }

    [Fact]
    public void Union_puts_parts_beyond_a_short_frame_at_the_origin()
    {
        var setup = Setup(0x02000001, [A.Id, B.Id, A.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(2, 0, 0))]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Union));
        Assert.Equal(3, set.Shapes.Count);
        Assert.Equal(Vector3.Zero, set.Shapes[2].LocalPosition);
    }

    [Theory]
    [InlineData(true, true, "Resting", 1f)]
    [InlineData(false, true, "Default", 2f)]
    public void Retail_prefers_resting_then_default(bool resting, bool @default, string used, float x)
    {
        var placements = new List<PlacementFrame>();
        if (@default) placements.Add(PlacementAt(Placement.Default, new Vector3(2, 0, 0)));
        if (resting) placements.Add(PlacementAt(Placement.Resting, new Vector3(1, 0, 0)));
        placements.Add(PlacementAt(0x66, new Vector3(3, 0, 0)));
        var set = ShadowShapeBuilder.Build(Setup(0x02000002, [A.Id], placements.ToArray()), Lookup(A), new(ShapePolicy.Retail));
        Assert.Equal(used, set.Placement.Used);
        Assert.Equal("Resting", set.Placement.Requested);
        Assert.Equal(x, set.Shapes.Single().LocalPosition.X);
    }

    [Fact]
    public void Retail_never_falls_back_to_another_placement_but_union_does()
    {
        var setup = Setup(0x02000003, [A.Id, B.Id], [PlacementAt(0x66, new(3, 0, 0), new(4, 0, 0))]);
        var retail = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Retail));
        Assert.Equal("None", retail.Placement.Used);
        Assert.Empty(retail.Shapes);
        Assert.Equal(2, retail.Diagnostics.Count(d => d.Code == DiagnosticCodes.NoPose));
        var union = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Union));
        Assert.Equal("Other", union.Placement.Used);
        Assert.Equal([3f, 4f], union.Shapes.Select(s => s.LocalPosition.X));
    }

    [Fact]
    public void Retail_single_part_without_placement_sits_at_the_origin()
    {
        var set = ShadowShapeBuilder.Build(Setup(0x02000004, [A.Id]), Lookup(A), new(ShapePolicy.Retail));
        var shape = Assert.Single(set.Shapes);
        Assert.Equal(Vector3.Zero, shape.LocalPosition);
        Assert.Equal("None", set.Placement.Used);
    }

    [Fact]
    public void Default_scale_z_and_entity_scale_multiply_radius_but_only_entity_scale_moves_the_part()
    {
        var setup = Setup(0x02000005, [A.Id, B.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(0, 2, 0))],
            defaultScale: [new(2, 2, 3), new(1, 1, 1)]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Retail, 2f));
        Assert.Equal(new Vector3(2, 0, 0), set.Shapes[0].LocalPosition);
        Assert.Equal(6f, set.Shapes[0].Scale);
        Assert.Equal(0.75f * 6f, set.Shapes[0].Radius);
        Assert.Equal(2f, set.Shapes[1].Scale);
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.NonUniformScale && d.Message.Contains("part 0"));
        var union = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Union, 2f));
        Assert.All(union.Shapes, s => Assert.Equal(2f, s.Scale));
    }

    [Fact]
    public void A_placement_with_a_frame_count_other_than_the_part_count_is_diagnosed()
    {
        // A dat stores one frame per part, so only an in-memory source can hand over another count.
        var shortFrame = ShadowShapeBuilder.Build(Setup(0x02000001, [A.Id, B.Id, A.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(2, 0, 0))]),
            Lookup(A, B), new(ShapePolicy.Retail));
        var longFrame = ShadowShapeBuilder.Build(Setup(0x02000001, [A.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(2, 0, 0))]),
            Lookup(A), new(ShapePolicy.Retail));
        Assert.Contains(shortFrame.Diagnostics, d => d.Code == DiagnosticCodes.FrameCount && d.Message.Contains("2 frame(s) for 3 part(s): parts past the last frame get no pose"));
        Assert.Contains(longFrame.Diagnostics, d => d.Code == DiagnosticCodes.FrameCount && d.Message.Contains("2 frame(s) for 1 part(s): the extra frames are ignored"));
        Assert.Equal(1f, Assert.Single(longFrame.Shapes).LocalPosition.X);
    }

    [Fact]
    public void A_default_scale_count_other_than_the_part_count_is_ignored_and_said()
    {
        var setup = Setup(0x02000005, [A.Id, B.Id], [PlacementAt(Placement.Resting, new(1, 0, 0), new(0, 2, 0))], defaultScale: [new(3, 3, 3)]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(A, B), new(ShapePolicy.Retail));
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.DefaultScaleCount && d.Message.Contains("1 entries for 2 parts"));
        Assert.All(set.Shapes, s => Assert.Equal(1f, s.Scale));
    }

    [Fact]
    public void Entity_scale_scales_cylinders_and_spheres()
    {
        var creature = Setup(0x02000006, [0x01000009], cyls: [new CylSphere(new(0, 0, 0.1f), 0.4f, 1.8f)]);
        var drawing = BoxGfxObj(0x01000009, physics: false);
        var set = ShadowShapeBuilder.Build(creature, Lookup(drawing), new(ShapePolicy.Retail, 1.5f));
        var cyl = Assert.Single(set.Shapes);
        Assert.Equal(CollisionType.Cylinder, cyl.CollisionType);
        Assert.Equal(0.4f * 1.5f, cyl.Radius);
        Assert.Equal(1.8f * 1.5f, cyl.CylHeight);
        Assert.Equal(0.1f * 1.5f, cyl.LocalPosition.Z);

        var item = Setup(0x02000007, [0x01000009], spheres: [new Sphere(new(0, 0, 0.2f), 0.3f)]);
        var sphere = Assert.Single(ShadowShapeBuilder.Build(item, Lookup(drawing), new(ShapePolicy.Retail, 2f)).Shapes);
        Assert.Equal(CollisionType.Sphere, sphere.CollisionType);
        Assert.Equal(0.6f, sphere.Radius);
        Assert.Equal(0.4f, sphere.LocalPosition.Z);
    }

    [Fact]
    public void Union_cylinder_without_height_gets_four_radii_and_zero_radius_is_skipped()
    {
        var setup = Setup(0x02000008, [], cyls: [new CylSphere(Vector3.Zero, 0.5f, 0), new CylSphere(Vector3.Zero, 0, 1)]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(), new(ShapePolicy.Union));
        var cyl = Assert.Single(set.Shapes);
        Assert.Equal(2f, cyl.CylHeight);
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.ZeroRadius);
    }

    [Fact]
    public void Missing_gfxobj_and_flag_mismatch_are_diagnosed_not_fatal()
    {
        var setup = Setup(0x02000009, [A.Id, 0x0100BEEF], [PlacementAt(Placement.Default, Vector3.Zero, Vector3.One)]);
        var set = ShadowShapeBuilder.Build(setup, Lookup(A), new(ShapePolicy.Retail));
        Assert.Single(set.Shapes);
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.MissingGfxObj && d.Message.Contains("0x0100BEEF"));
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.FlagMismatch);
    }

    [Fact]
    public void Nothing_to_collide_is_reported()
    {
        var set = ShadowShapeBuilder.Build(Setup(0x0200000A, [0x01000009]), Lookup(BoxGfxObj(0x01000009, physics: false)), new(ShapePolicy.Retail));
        Assert.Empty(set.Shapes);
        Assert.Contains(set.Diagnostics, d => d.Code == DiagnosticCodes.NoShapes);
    }

    /// <summary>Issue 32 item 9: a NaN Sphere radius or an infinite Setup Radius on a BSP object builds no shape from them, and is still said.</summary>
    [Fact]
    public void A_NaN_sphere_radius_and_an_infinite_setup_radius_are_non_finite_diagnostics_even_when_no_shape_uses_them()
    {
        var setup = Setup(0x0200000C, [0x0100000C], spheres: [new Sphere(Vector3.Zero, float.NaN)], radius: float.PositiveInfinity);
        foreach (var policy in new[] { ShapePolicy.Retail, ShapePolicy.Union })
        {
            var set = ShadowShapeBuilder.Build(setup, Lookup(BoxGfxObj(0x0100000C)), new(policy));
            var nonFinite = set.Diagnostics.Where(d => d.Code == DiagnosticCodes.NonFinite).Select(d => d.Message).ToArray();
            Assert.Contains(nonFinite, m => m.StartsWith("Sphere 0: ", StringComparison.Ordinal));
            Assert.Contains(nonFinite, m => m.StartsWith("Setup Radius x Height: non-finite (", StringComparison.Ordinal));
            Assert.Equal(nonFinite.Distinct().Count(), nonFinite.Length);
        }
    }

    [Fact]
    public void Bsp_local_sphere_is_the_root_sphere_moved_into_entity_space()
    {
        var rotated = new PlacementFrame(Placement.Resting, [new Frame(new Vector3(1, 2, 3), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI))]);
        var gfx = BoxGfxObj(0x0100000B) with { PhysicsBsp = BoxGfxObj(0x0100000B).PhysicsBsp! with { BoundingSphere = new Sphere(new Vector3(1, 0, 0), 2) } };
        var shape = ShadowShapeBuilder.Build(Setup(0x0200000B, [gfx.Id], [rotated]), Lookup(gfx), new(ShapePolicy.Retail)).Shapes.Single();
        Assert.Equal(2f, shape.Radius);
        Assert.Equal(0f, shape.LocalSphere!.Value.Center.X, 5);
        Assert.Equal(2f, shape.LocalSphere.Value.Center.Y, 5);
        Assert.Equal(3f, shape.LocalSphere.Value.Center.Z, 5);
    }
}
