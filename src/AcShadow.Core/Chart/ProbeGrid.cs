using System.Numerics;

namespace AcShadow.Core.Chart;

/// <summary>
/// The 3-D grid of query spheres around an object: the object's bounds grown by the margin, points on
/// multiples of the spacing in x and y and at walking height + k × spacing in z (so the failure map's
/// slice is a grid layer). A grid above <see cref="ChartOptions.MaxGridProbes"/> is coarsened by doubling
/// the spacing until it fits.
/// </summary>
public static class ProbeGrid
{
    public sealed record Result(IReadOnlyList<Probe> Probes, float Spacing, Bounds Region);

    public static Result Build(Bounds objectBounds, ChartOptions options)
    {
        var region = objectBounds.IsEmpty
            ? new Bounds(new Vector3(-options.EffectiveMargin), new Vector3(options.EffectiveMargin))
            : objectBounds.Expand(options.EffectiveMargin);
        var walk = options.EffectiveWalkHeight;
        var spacing = options.Spacing;
        while (true)
        {
            var (x0, nx) = Steps(region.Min.X, region.Max.X, 0f, spacing);
            var (y0, ny) = Steps(region.Min.Y, region.Max.Y, 0f, spacing);
            var (z0, nz) = Steps(region.Min.Z, region.Max.Z, walk, spacing);
            if ((long)nx * ny * nz > options.MaxGridProbes && spacing < 1e3f) { spacing *= 2f; continue; }
            var probes = new List<Probe>(nx * ny * nz);
            for (var k = 0; k < nz; k++)
                for (var j = 0; j < ny; j++)
                    for (var i = 0; i < nx; i++)
                        probes.Add(new Probe(new Vector3((x0 + i) * spacing, (y0 + j) * spacing, walk + (z0 + k) * spacing), options.ProbeRadius, ProbeKind.Grid));
            return new Result(probes, spacing, region);
        }
    }

    /// <summary>First step index and count of the points origin + k·step inside [min, max].</summary>
    private static (int First, int Count) Steps(float min, float max, float origin, float step)
    {
        var first = (int)MathF.Ceiling((min - origin) / step);
        var last = (int)MathF.Floor((max - origin) / step);
        return (first, Math.Max(1, last - first + 1));
    }
}
