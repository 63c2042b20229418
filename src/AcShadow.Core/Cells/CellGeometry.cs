using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Cells;

/// <summary>
/// What one cell structure contributes to every cell that uses it: its physics polygons with retail
/// planes and its PhysicsBSP, flattened exactly as a GfxObj's (<see cref="BspExtractor"/>: same planes,
/// same diagnostics), and its drawing polygons by id, so a cell's portals can be resolved. Built once per
/// (Environment, cell structure) however many cells share it.
/// </summary>
public sealed class CellGeometry
{
    private readonly IReadOnlyDictionary<ushort, Vector3> _vertices;
    private readonly Dictionary<ushort, Polygon> _polygons;

    /// <summary>The physics BSP dump; its id is the Environment's until a cell file names its cell.</summary>
    public BspDump Physics { get; }

    public string Subject { get; }

    private CellGeometry(uint environmentId, uint index, CellStruct cell)
    {
        Subject = $"Environment 0x{environmentId:X8} cell structure {index}";
        _vertices = cell.Vertices;
        _polygons = [];
        foreach (var (key, polygon) in cell.Polygons) _polygons.TryAdd(key, polygon);
        // The extractor reads a GfxObj; a cell structure's physics part has exactly that shape.
        var asGfxObj = new GfxObj(environmentId, GfxObjFlags.HasPhysics, [], cell.Vertices, cell.PhysicsPolygons, cell.PhysicsBsp, default, []);
        var dump = BspExtractor.Extract(asGfxObj)!;
        var prefix = $"GfxObj 0x{environmentId:X8}";
        Physics = dump with { Diagnostics = dump.Diagnostics.Select(d => d.StartsWith(prefix, StringComparison.Ordinal) ? Subject + d[prefix.Length..] : d).ToArray() };
    }

    public static CellGeometry Of(CellEnvironment environment, uint index, CellStruct cell) => new(environment.Id, index, cell);

    /// <summary>
    /// A portal's polygon in the cell's frame and its retail plane (<see cref="PolygonPlane"/>), or why it
    /// cannot be given (a polygon id the structure lacks, a vertex it lacks, a degenerate polygon: no plane).
    /// </summary>
    public (IReadOnlyList<Vector3> Vertices, Plane? Plane, string? Problem) Portal(ushort polygonId)
    {
        if (!_polygons.TryGetValue(polygonId, out var polygon))
            return ([], null, $"{Subject}: portal polygon {polygonId} is not one of its polygons");
        var points = new List<Vector3>(polygon.VertexIds.Count);
        foreach (var id in polygon.VertexIds)
        {
            if (!_vertices.TryGetValue((ushort)id, out var p))
                return (points, null, $"{Subject}: portal polygon {polygonId} uses vertex {id}, which it does not have");
            points.Add(p);
        }
        var plane = PolygonPlane.Compute(points);
        return (points, plane, plane is null ? $"{Subject}: portal polygon {polygonId} is degenerate, no plane" : null);
    }
}
