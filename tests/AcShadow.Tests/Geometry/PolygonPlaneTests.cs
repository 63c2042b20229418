using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Geometry;

public class PolygonPlaneTests
{
    [Fact]
    public void Quad_plane_matches_hand_computed_float32_bits()
    {
        // Expected bits worked out step by step in float32 (each operation rounded to single precision):
        // fan normal sum over (v1,v2) and (v2,v3), normalised; d = -(Σ dot(n, v)) / 4.
        var quad = new[]
        {
            new Vector3(0.1f, 0.2f, 0.3f), new Vector3(1.7f, -0.4f, 0.9f),
            new Vector3(0.5f, 1.3f, -0.2f), new Vector3(-0.3f, 0.8f, 0.1f),
        };
        var plane = PolygonPlane.Compute(quad)!.Value;
        Assert.Equal(0xBDBF1CD5u, Bits(plane.Normal.X));
        Assert.Equal(0x3EE13D6Eu, Bits(plane.Normal.Y));
        Assert.Equal(0x3F64A716u, Bits(plane.Normal.Z));
        Assert.Equal(0xBED0DBE0u, Bits(plane.D));
    }

    [Fact]
    public void Axis_aligned_triangle_gives_exact_plane()
    {
        var plane = PolygonPlane.Compute([new(0, 0, 2), new(1, 0, 2), new(0, 1, 2)])!.Value;
        Assert.Equal(new Vector3(0, 0, 1), plane.Normal);
        Assert.Equal(-2f, plane.D);
    }

    [Fact]
    public void Winding_decides_the_normal_direction()
    {
        var ccw = PolygonPlane.Compute([new(0, 0, 0), new(1, 0, 0), new(0, 1, 0)])!.Value;
        var cw = PolygonPlane.Compute([new(0, 0, 0), new(0, 1, 0), new(1, 0, 0)])!.Value;
        Assert.Equal(1f, ccw.Normal.Z);
        Assert.Equal(-1f, cw.Normal.Z);
    }

    [Fact]
    public void Collinear_and_repeated_vertices_have_no_plane()
    {
        Assert.Null(PolygonPlane.Compute([new(0, 0, 0), new(1, 0, 0), new(2, 0, 0)]));
        Assert.Null(PolygonPlane.Compute([new(1, 1, 1), new(1, 1, 1), new(1, 1, 1), new(1, 1, 1)]));
        Assert.Null(PolygonPlane.Compute([new(0, 0, 0), new(1, 0, 0)]));
    }

    [Fact]
    public void Non_planar_quad_reports_its_deviation()
    {
        var quad = new Vector3[] { new(0, 0, 0), new(1, 0, 0), new(1, 1, 0.2f), new(0, 1, 0) };
        var plane = PolygonPlane.Compute(quad)!.Value;
        Assert.True(PolygonPlane.MaxDeviation(plane, quad) > 0.01f);
        var flat = new Vector3[] { new(0, 0, 0), new(1, 0, 0), new(1, 1, 0), new(0, 1, 0) };
        Assert.Equal(0f, PolygonPlane.MaxDeviation(PolygonPlane.Compute(flat)!.Value, flat));
    }

    private static uint Bits(float f) => BitConverter.SingleToUInt32Bits(f);
}
