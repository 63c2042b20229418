using System.Numerics;

namespace AcShadow.Fixtures.Geometry;

/// <summary>
/// A polygon's plane as retail computes it (CPolygon::make_plane), in float32:
/// normal = normalize(Σ cross(v[j]−v[0], v[j+1]−v[0])) over the fan j = 1..n−2,
/// d = −(Σ dot(normal, v[k])) / n over all n vertices.
/// Written as explicit scalar float arithmetic in a fixed order so every machine gets the same bits
/// (no SIMD reassociation, no fused multiply-add).
/// </summary>
internal static class PolygonPlane
{
    /// <summary>The plane, or null when the fan's normal has zero length (collinear or repeated vertices).</summary>
    public static Plane? Compute(IReadOnlyList<Vector3> vertices)
    {
        var n = vertices.Count;
        if (n < 3) return null;
        var v0 = vertices[0];
        float nx = 0f, ny = 0f, nz = 0f;
        for (var j = 1; j < n - 1; j++)
        {
            var a = Sub(vertices[j], v0);
            var b = Sub(vertices[j + 1], v0);
            nx += a.Y * b.Z - a.Z * b.Y;
            ny += a.Z * b.X - a.X * b.Z;
            nz += a.X * b.Y - a.Y * b.X;
        }
        var lengthSquared = nx * nx + ny * ny + nz * nz;
        var length = MathF.Sqrt(lengthSquared);
        if (!(length > 0f) || !float.IsFinite(length)) return null;
        var normal = new Vector3(nx / length, ny / length, nz / length);
        var sum = 0f;
        for (var k = 0; k < n; k++) sum += Dot(normal, vertices[k]);
        return new Plane(normal, -(sum / n));
    }

    /// <summary>Signed distance of a point from a plane: dot(normal, p) + d, in a fixed float order.</summary>
    public static float Distance(Plane plane, Vector3 p) => Dot(plane.Normal, p) + plane.D;

    /// <summary>dot(a, b) summed x, then y, then z.</summary>
    public static float Dot(Vector3 a, Vector3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

    private static Vector3 Sub(Vector3 a, Vector3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>The largest distance of any vertex from the plane: 0 for a planar polygon.</summary>
    public static float MaxDeviation(Plane plane, IReadOnlyList<Vector3> vertices)
    {
        var max = 0f;
        // By index: a foreach over the interface boxes the list's enumerator, once per polygon of every dump.
        for (var i = 0; i < vertices.Count; i++) max = MathF.Max(max, MathF.Abs(Distance(plane, vertices[i])));
        return max;
    }
}
