
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// The vertical counterpart of <see cref="FootprintCoverage"/>: the share of the BSP parts' height range
/// [zMin, zMax] (over every posed physics-polygon vertex) that the fallback cylinder's [0, Height] spans.
/// A 0.2 m "soda can" at the foot of a 2.2 m door spans about 0.09 of it.
/// </summary>
public static class HeightCoverage
{
    /// <summary>Rounded to 4 decimals; null when there are no vertices or they span no height.</summary>
    public static double? Measure(IReadOnlyList<FootprintCoverage.PosedPart> parts, float height)
    {
        double min = double.MaxValue, max = double.MinValue;
        foreach (var part in parts)
            foreach (var (_, polygon) in part.GfxObj.PhysicsPolygons)
                foreach (var vid in polygon.VertexIds)
                {
                    if (vid < 0 || !part.GfxObj.Vertices.TryGetValue((ushort)vid, out var v)) continue;
                    // An audit measure rounded to 4 decimals, no client counterpart: the plain rotation of the posed part.
                    double z = (part.Position + QuaternionRotation.Rotate(part.Rotation, v * part.Scale)).Z;
                    min = Math.Min(min, z);
                    max = Math.Max(max, z);
                }
        if (!(max > min)) return null;
        var overlap = Math.Min(max, height) - Math.Max(min, 0d);
        return Math.Round(Math.Max(0d, overlap) / (max - min), 4);
    }
}
