using System.Numerics;

namespace AcShadow.Analysis.Chart;

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
            // Coarsened until it fits, however large the object (a huge --scale): the probe count, not the
            // spacing, is what memory and time answer to.
            if ((double)nx * ny * nz > options.MaxGridProbes) { spacing *= 2f; continue; }
            var probes = new List<Probe>((int)(nx * ny * nz));
            for (var k = 0L; k < nz; k++)
                for (var j = 0L; j < ny; j++)
                    for (var i = 0L; i < nx; i++)
                        probes.Add(new Probe(new Vector3((x0 + i) * spacing, (y0 + j) * spacing, walk + (z0 + k) * spacing), options.ProbeRadius, ProbeKind.Grid));
            return new Result(probes, spacing, region);
        }
    }

    /// <summary>First step index and count of the points origin + k·step inside [min, max].</summary>
    private static (long First, long Count) Steps(float min, float max, float origin, float step)
    {
        // In double and clamped: a region far larger than the step must not overflow into a negative count.
        var first = Math.Ceiling(((double)min - origin) / step);
        var last = Math.Floor(((double)max - origin) / step);
        var count = Math.Clamp(last - first + 1, 1, 1e12);
        return ((long)Math.Clamp(first, -1e15, 1e15), (long)count);
    }
}
