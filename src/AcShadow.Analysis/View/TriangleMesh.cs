using System.Numerics;

namespace AcShadow.Analysis.View;

/// <summary>
/// Triangles with flat normals: every face has its own vertices (so its own normal), and the triangles of a
/// polygon share the polygon's. <see cref="Indices"/> holds three per triangle, counter-clockwise seen from
/// the side the normal points to. Positions are in the dat's axes (x east, y north, z up), metres.
/// </summary>
public sealed class TriangleMesh
{
    private readonly List<Vector3> _positions = [];
    private readonly List<Vector3> _normals = [];
    private readonly List<int> _indices = [];

    public IReadOnlyList<Vector3> Positions => _positions;
    public IReadOnlyList<Vector3> Normals => _normals;
    public IReadOnlyList<int> Indices => _indices;
    public int TriangleCount => _indices.Count / 3;
    public bool IsEmpty => _indices.Count == 0;

    /// <summary>A convex-enough polygon as a fan from its first vertex, all its vertices given <paramref name="normal"/>.</summary>
    public void AddPolygon(IReadOnlyList<Vector3> vertices, Vector3 normal)
    {
        if (vertices.Count < 3) return;
        var first = _positions.Count;
        foreach (var v in vertices)
        {
            _positions.Add(v);
            _normals.Add(normal);
        }
        for (var j = 1; j + 1 < vertices.Count; j++)
        {
            _indices.Add(first);
            _indices.Add(first + j);
            _indices.Add(first + j + 1);
        }
    }

    /// <summary>A face whose normal is its own (for tessellated cylinders and spheres); a face with no area is left out.</summary>
    public void AddFace(params Vector3[] vertices)
    {
        if (FaceNormal(vertices[0], vertices[1], vertices[2]) is { } normal) AddPolygon(vertices, normal);
    }

    /// <summary>normalize((b − a) × (c − a)) in scalar float arithmetic (the same bits on every machine); null when the face has no area.</summary>
    internal static Vector3? FaceNormal(Vector3 a, Vector3 b, Vector3 c)
    {
        float ux = b.X - a.X, uy = b.Y - a.Y, uz = b.Z - a.Z;
        float vx = c.X - a.X, vy = c.Y - a.Y, vz = c.Z - a.Z;
        float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        var length = MathF.Sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 1e-12f)) return null;
        return new Vector3(nx / length, ny / length, nz / length);
    }
}
