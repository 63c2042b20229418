using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Tests.Collision;

/// <summary>
/// The nearest-polygon distance skips boxes of polygons it can prove are farther: it must give the very
/// bits that measuring every polygon gives, on the sample's and the forged parts, near and far, and on
/// points far outside any real object (where float rounding is coarsest).
/// </summary>
public class NearestPolygonIndexTests
{
    [Fact]
    public void The_indexed_distance_is_bit_for_bit_the_minimum_over_every_polygon()
    {
        var parts = CollisionCorpus.Sample.Select(CompiledBsp.Compile)
            .Concat(CollisionCorpus.Forged().Select(f => CompiledBsp.Compile(f.Dump))).ToArray();
        Assert.Contains(parts, p => p.Polygons.Length > 50);
        var random = new Random(11);
        var checkedPoints = 0;
        foreach (var bsp in parts)
        {
            foreach (var (center, _, _) in StressProbes.For(bsp, 300, 5)) Check(bsp, center);
            var root = bsp.Nodes.Length > 0 ? bsp.Nodes[0] : default;
            for (var i = 0; i < 100; i++)
            {
                var spread = root.SphereRadius * (i < 50 ? 1.5f : 40f) + 1f;
                Check(bsp, root.SphereCenter + new Vector3(Next(random), Next(random), Next(random)) * spread);
            }
            Check(bsp, new Vector3(3e30f, -2e30f, 1e30f));
            checkedPoints += 403;
        }
        Assert.True(checkedPoints > 1000);

        static float Next(Random random) => (float)(random.NextDouble() * 2 - 1);
    }

    [Fact]
    public void A_part_without_polygons_is_infinitely_far_and_a_nan_point_gives_nan()
    {
        var part = CompiledBsp.Compile(CollisionCorpus.Sample.First());
        Assert.True(float.IsNaN(SurfaceDistance.ToNearestPolygon(part, new Vector3(float.NaN, 0, 0))));
        var empty = CompiledBsp.Compile(CollisionCorpus.Sample.First() with { Polygons = [], Nodes = [] });
        Assert.Equal(float.PositiveInfinity, SurfaceDistance.ToNearestPolygon(empty, Vector3.One));
    }

    private static void Check(CompiledBsp bsp, Vector3 point)
    {
        var every = float.PositiveInfinity;
        foreach (var polygon in bsp.Polygons) every = MathF.Min(every, SurfaceDistance.ToPolygon(polygon, point));
        var indexed = SurfaceDistance.ToNearestPolygon(bsp, point);
        Assert.True(BitConverter.SingleToInt32Bits(every) == BitConverter.SingleToInt32Bits(indexed),
            $"GfxObj 0x{bsp.GfxObjId:X8} at ({point.X:R}, {point.Y:R}, {point.Z:R}): every polygon {every:R}, indexed {indexed:R}");
    }
}
