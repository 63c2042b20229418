using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Tests.Support.Records;

namespace AcShadow.Tests.Collision;

/// <summary>What the object query does with shapes it cannot use as they are: each is said, with its code, and none crashes it.</summary>
public class ObjectOverlapQueryTests
{
    private static readonly GfxObj Box = BoxGfxObj(0x01000001);
    private static readonly CompiledBsp BoxBsp = CompiledBsp.Compile(BspExtractor.Extract(Box)!);

    private static ShadowShape BoxShape() =>
        Assert.Single(ShadowShapeBuilder.Build(Setup(0x02000001, [Box.Id]), Lookup(Box), new(ShapePolicy.Retail)).Shapes);

    private static CompiledBsp? Bsps(uint id) => id == Box.Id ? BoxBsp : null;

    [Fact]
    public void Shapes_the_query_cannot_use_are_skipped_and_a_rotation_not_of_unit_length_is_normalised()
    {
        var shape = BoxShape();
        var unit = ObjectOverlapQuery.Create([shape], Bsps);
        var doubled = ObjectOverlapQuery.Create([shape with { LocalRotation = new Quaternion(0, 0, 0, 2) }], Bsps);
        var unusable = ObjectOverlapQuery.Create(
            [shape with { Scale = 0f }, shape with { GfxObjId = 0x0100FFFF }, shape with { LocalPosition = new(float.NaN, 0, 0) }], Bsps);

        Assert.Empty(unit.Diagnostics);
        Assert.Contains(doubled.Diagnostics, d => d.Code == CollisionDiagnosticCodes.NormalisedRotation && d.Message.Contains("of length 2 normalised"));
        Assert.True(doubled.Overlaps(Vector3.Zero, 0.1f));
        Assert.Equal(unit.Overlaps(new(0.55f, 0, 0), 0.1f), doubled.Overlaps(new(0.55f, 0, 0), 0.1f));
        Assert.Equal(3, unusable.Diagnostics.Count(d => d.Code == CollisionDiagnosticCodes.SkippedShape));
        Assert.Contains(unusable.Diagnostics, d => d.Message.Contains("no PhysicsBSP for GfxObj 0x0100FFFF"));
        Assert.False(unusable.Overlaps(Vector3.Zero, 0.1f));
    }

    [Fact]
    public void More_than_twelve_diagnostics_of_one_code_are_counted_in_one_line()
    {
        var shape = BoxShape() with { Scale = 0f };
        var query = ObjectOverlapQuery.Create(Enumerable.Repeat(shape, 15), Bsps);
        Assert.Equal(12, query.Diagnostics.Count(d => d.Code == CollisionDiagnosticCodes.SkippedShape));
        var more = Assert.Single(query.Diagnostics, d => d.Code == CollisionDiagnosticCodes.Truncated);
        Assert.Equal($"3 more {CollisionDiagnosticCodes.SkippedShape} diagnostic(s) not listed", more.Message);
    }
}
