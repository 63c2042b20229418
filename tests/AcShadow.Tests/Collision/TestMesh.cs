using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Collision;

/// <summary>Polygon soups for collision tests: vertices and polygons as vertex-index lists, outward wound.</summary>
public sealed record TestMesh(IReadOnlyList<Vector3> Vertices, IReadOnlyList<short[]> Polygons)
{
    public static TestMesh Box(Vector3 center, Vector3 half, Quaternion? rotation = null)
    {
        var q = rotation ?? Quaternion.Identity;
        var corners = new Vector3[8];
        for (var i = 0; i < 8; i++)
        {
            var local = new Vector3((i & 1) == 0 ? -half.X : half.X, (i & 2) == 0 ? -half.Y : half.Y, (i & 4) == 0 ? -half.Z : half.Z);
            corners[i] = center + Vector3.Transform(local, q);
        }
        short[][] faces = [[0, 2, 6, 4], [1, 3, 7, 5], [0, 1, 5, 4], [2, 3, 7, 6], [0, 1, 3, 2], [4, 5, 7, 6]];
        return new TestMesh(corners, faces.Select(f => Outward(corners, f, center)).ToArray());
    }

    /// <summary>A triangular prism (wedge): a ramp rising along +X.</summary>
    public static TestMesh Wedge(Vector3 origin, float length, float width, float height)
    {
        Vector3[] v =
        [
            origin, origin + new Vector3(length, 0, 0), origin + new Vector3(length, 0, height),
            origin + new Vector3(0, width, 0), origin + new Vector3(length, width, 0), origin + new Vector3(length, width, height),
        ];
        var centroid = v.Aggregate(Vector3.Zero, (a, b) => a + b) / v.Length;
        short[][] faces = [[0, 1, 2], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [0, 2, 5, 3]];
        return new TestMesh(v, faces.Select(f => Outward(v, f, centroid)).ToArray());
    }

    /// <summary>One open quad facing +Z (a floor with nothing under it).</summary>
    public static TestMesh Floor(float halfX, float halfY, float z) =>
        new([new(-halfX, -halfY, z), new(halfX, -halfY, z), new(halfX, halfY, z), new(-halfX, halfY, z)], [[0, 1, 2, 3]]);

    /// <summary>
    /// The mesh with vertex <paramref name="index"/> moved by <paramref name="offset"/>: the faces that share
    /// it stop being planar (retail tests such a polygon against its averaged plane).
    /// </summary>
    public TestMesh Pulled(int index, Vector3 offset) =>
        new(Vertices.Select((v, i) => i == index ? v + offset : v).ToArray(), Polygons);

    public TestMesh Plus(TestMesh other)
    {
        var offset = (short)Vertices.Count;
        return new TestMesh([.. Vertices, .. other.Vertices],
            [.. Polygons, .. other.Polygons.Select(p => p.Select(i => (short)(i + offset)).ToArray())]);
    }

    public TestMesh WithPolygon(short[] polygon, params Vector3[] newVertices)
    {
        var offset = (short)Vertices.Count;
        return new TestMesh([.. Vertices, .. newVertices], [.. Polygons, polygon.Select(i => i < 0 ? (short)(offset + (-i - 1)) : i).ToArray()]);
    }

    private static short[] Outward(Vector3[] v, short[] face, Vector3 inside)
    {
        var plane = PolygonPlane.Compute(face.Select(i => v[i]).ToArray())!.Value;
        var faceCenter = face.Aggregate(Vector3.Zero, (a, i) => a + v[i]) / face.Length;
        return Vector3.Dot(plane.Normal, faceCenter - inside) >= 0 ? face : face.Reverse().ToArray();
    }
}
