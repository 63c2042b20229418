using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// How much of a Setup's BSP footprint the single Radius×Height cylinder fallback covers.
/// Footprint F: the union of the top-down (XY) projections of every physics polygon of every posed BSP
/// part (part-local vertex × part scale, rotated by the part's orientation, moved to its position).
/// Disk C: radius Setup.Radius × entity scale about the entity origin (where the cylinder stands).
/// Coverage = area(F ∩ C) / area(F), measured on a grid of square cells over F's bounding box, 256 cells
/// along its longer side; a cell counts when its centre lies in F (even-odd rule per polygon), and in C
/// when its centre does. Deterministic: fixed grid, scalar double arithmetic, fixed order. Vertical
/// polygons project to segments and add no area; a closed solid's footprint comes from its other faces.
/// </summary>
public static class FootprintCoverage
{
    public const int GridCells = 256;

    /// <summary>A BSP part as posed in the entity: its GfxObj, position, orientation and uniform scale.</summary>
    public readonly record struct PosedPart(GfxObj GfxObj, Vector3 Position, Quaternion Rotation, float Scale);

    /// <summary>Coverage in [0, 1] and the footprint area in m², both rounded to 4 decimals; null when F has no area.</summary>
    public static (double Coverage, double Area)? Measure(IReadOnlyList<PosedPart> parts, float radius)
    {
        var polygons = new List<(double X, double Y)[]>();
        foreach (var part in parts)
            foreach (var (_, polygon) in part.GfxObj.PhysicsPolygons)
            {
                var points = new List<(double, double)>(polygon.VertexIds.Count);
                foreach (var vid in polygon.VertexIds)
                {
                    if (vid < 0 || !part.GfxObj.Vertices.TryGetValue((ushort)vid, out var v)) { points.Clear(); break; }
                    // An audit measure rounded to 4 decimals, no client counterpart: the plain rotation of the posed part.
                    var p = part.Position + QuaternionRotation.Rotate(part.Rotation, v * part.Scale);
                    points.Add((p.X, p.Y));
                }
                if (points.Count >= 3) polygons.Add(points.ToArray());
            }
        if (polygons.Count == 0) return null;

        double minX = double.MaxValue, minY = double.MaxValue, maxX = double.MinValue, maxY = double.MinValue;
        foreach (var poly in polygons)
            foreach (var (x, y) in poly)
            {
                minX = Math.Min(minX, x); maxX = Math.Max(maxX, x);
                minY = Math.Min(minY, y); maxY = Math.Max(maxY, y);
            }
        var extent = Math.Max(maxX - minX, maxY - minY);
        if (!(extent > 0) || !double.IsFinite(extent)) return null;
        var cell = extent / GridCells;
        var nx = Math.Max(1, (int)Math.Ceiling((maxX - minX) / cell));
        var ny = Math.Max(1, (int)Math.Ceiling((maxY - minY) / cell));
        var inside = new bool[nx * ny];

        foreach (var poly in polygons)
        {
            double pMinX = double.MaxValue, pMinY = double.MaxValue, pMaxX = double.MinValue, pMaxY = double.MinValue;
            foreach (var (x, y) in poly)
            {
                pMinX = Math.Min(pMinX, x); pMaxX = Math.Max(pMaxX, x);
                pMinY = Math.Min(pMinY, y); pMaxY = Math.Max(pMaxY, y);
            }
            var i0 = Math.Max(0, (int)Math.Floor((pMinX - minX) / cell - 0.5));
            var i1 = Math.Min(nx - 1, (int)Math.Ceiling((pMaxX - minX) / cell - 0.5));
            var j0 = Math.Max(0, (int)Math.Floor((pMinY - minY) / cell - 0.5));
            var j1 = Math.Min(ny - 1, (int)Math.Ceiling((pMaxY - minY) / cell - 0.5));
            for (var j = j0; j <= j1; j++)
            {
                var cy = minY + (j + 0.5) * cell;
                for (var i = i0; i <= i1; i++)
                {
                    if (inside[j * nx + i]) continue;
                    var cx = minX + (i + 0.5) * cell;
                    if (Contains(poly, cx, cy)) inside[j * nx + i] = true;
                }
            }
        }

        long footprint = 0, covered = 0;
        var r2 = (double)radius * radius;
        for (var j = 0; j < ny; j++)
        {
            var cy = minY + (j + 0.5) * cell;
            for (var i = 0; i < nx; i++)
            {
                if (!inside[j * nx + i]) continue;
                footprint++;
                var cx = minX + (i + 0.5) * cell;
                if (cx * cx + cy * cy <= r2) covered++;
            }
        }
        if (footprint == 0) return null;
        return (Math.Round((double)covered / footprint, 4), Math.Round(footprint * cell * cell, 4));
    }

    /// <summary>Even-odd crossing test (a horizontal ray to +x).</summary>
    private static bool Contains((double X, double Y)[] poly, double x, double y)
    {
        var inside = false;
        for (int i = 0, j = poly.Length - 1; i < poly.Length; j = i++)
        {
            var (xi, yi) = poly[i];
            var (xj, yj) = poly[j];
            if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
        }
        return inside;
    }
}
