using System.Globalization;
using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Forging.Spec;

namespace AcShadow.Forging.Geometry;

/// <summary>
/// Accumulates vertices (shared by exact position, so boxes come out watertight) and polygons for a
/// GfxObj spec. Polygon winding decides the retail plane normal (fan cross product), so every helper
/// winds its faces to point outward.
/// </summary>
public sealed class MeshBuilder
{
    private readonly List<Vector3> _vertices = [];
    private readonly Dictionary<Vector3, int> _index = [];
    private readonly List<PolygonSpec> _polygons = [];

    public int PolygonCount => _polygons.Count;

    public int Vertex(Vector3 p)
    {
        if (_index.TryGetValue(p, out var id)) return id;
        _index[p] = _vertices.Count;
        _vertices.Add(p);
        return _vertices.Count - 1;
    }

    /// <summary>A polygon through the points in order; its normal is (p1 − p0) × (p2 − p0).</summary>
    public MeshBuilder Polygon(IEnumerable<Vector3> points, string? sidesType = null)
    {
        _polygons.Add(new PolygonSpec { Vertices = points.Select(Vertex).ToArray(), SidesType = sidesType });
        return this;
    }

    /// <summary>
    /// A grid of quads: cell (i, j) has corners point(i, j), point(i+1, j), point(i+1, j+1), point(i, j+1),
    /// so its normal is along (∂u × ∂v). <paramref name="skip"/> leaves holes (door openings).
    /// </summary>
    public MeshBuilder Grid(Func<int, int, Vector3> point, int nu, int nv, string? sidesType = null, Func<int, int, bool>? skip = null)
    {
        for (var j = 0; j < nv; j++)
            for (var i = 0; i < nu; i++)
                if (skip is null || !skip(i, j))
                    Polygon([point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)], sidesType);
        return this;
    }

    /// <summary>An axis-aligned closed box, outward normals, each face an (n × n) grid along its axes.</summary>
    public MeshBuilder Box(Vector3 min, Vector3 max, int nx = 1, int ny = 1, int nz = 1, string? sidesType = null)
    {
        // Lattice coordinates computed once per axis so neighbouring faces share vertices bit for bit.
        var xs = Steps(min.X, max.X, nx);
        var ys = Steps(min.Y, max.Y, ny);
        var zs = Steps(min.Z, max.Z, nz);
        Grid((j, k) => new(max.X, ys[j], zs[k]), ny, nz, sidesType);            // +X
        Grid((k, j) => new(min.X, ys[j], zs[k]), nz, ny, sidesType);            // −X
        Grid((k, i) => new(xs[i], max.Y, zs[k]), nz, nx, sidesType);            // +Y
        Grid((i, k) => new(xs[i], min.Y, zs[k]), nx, nz, sidesType);            // −Y
        Grid((i, j) => new(xs[i], ys[j], max.Z), nx, ny, sidesType);            // +Z
        Grid((j, i) => new(xs[i], ys[j], min.Z), ny, nx, sidesType);            // −Z
        return this;
    }

    /// <summary>A closed upright prism (a cylinder when <paramref name="sides"/> is large), outward normals.</summary>
    public MeshBuilder Prism(Vector3 baseCenter, float radius, float height, int sides, int rings = 1, string? sidesType = null)
    {
        var ring = new Vector3[sides];
        var zs = Steps(baseCenter.Z, baseCenter.Z + height, rings);
        Vector3 At(int s, int r)
        {
            var a = 2 * Math.PI * (s % sides) / sides;
            return new Vector3(baseCenter.X + radius * (float)Math.Cos(a), baseCenter.Y + radius * (float)Math.Sin(a), zs[r]);
        }
        Grid(At, sides, rings, sidesType);
        Polygon(Enumerable.Range(0, sides).Select(s => At(s, rings)), sidesType);
        Polygon(Enumerable.Range(0, sides).Reverse().Select(s => At(s, 0)), sidesType);
        return this;
    }

    public static float[] Steps(float from, float to, int n) =>
        Enumerable.Range(0, n + 1).Select(i => i == n ? to : from + (to - from) * i / n).ToArray();

    public GfxObjSpec ToSpec(uint id, bool physics, bool drawing, string? comment = null) => new()
    {
        Id = $"0x{id:X8}",
        Comment = comment,
        Vertices = _vertices.Select(v => new[] { Tidy(v.X), Tidy(v.Y), Tidy(v.Z) }).ToArray(),
        Polygons = _polygons.ToArray(),
        Physics = physics,
        Drawing = drawing,
    };

    /// <summary>
    /// A cell shape: the first <paramref name="wallCount"/> polygons are its walls, floors and ceilings,
    /// the rest its portal polygons (openings to other cells or outside).
    /// </summary>
    public CellStructSpec ToCellStructSpec(int wallCount, string? comment = null) => new()
    {
        Comment = comment,
        Vertices = _vertices.Select(v => new[] { Tidy(v.X), Tidy(v.Y), Tidy(v.Z) }).ToArray(),
        Polygons = _polygons.Take(wallCount).ToArray(),
        Portals = _polygons.Skip(wallCount).ToArray(),
    };

    /// <summary>The shortest decimal that reads back as the same float (0.965f → 0.965, not 0.96499997...).</summary>
    private static double Tidy(float f) => double.Parse(f.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
}
