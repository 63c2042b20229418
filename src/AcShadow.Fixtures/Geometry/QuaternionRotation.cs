using System.Numerics;

namespace AcShadow.Fixtures.Geometry;

/// <summary>
/// Rotating by a quaternion in explicit scalar float arithmetic, so results are bit-identical on every
/// machine (System.Numerics may vectorise and reassociate).
/// </summary>
internal static class QuaternionRotation
{
    /// <summary>v' = v + w·t + q×t with t = 2·(q×v), for a unit quaternion q.</summary>
    public static Vector3 Rotate(Quaternion q, Vector3 v)
    {
        var tx = 2f * (q.Y * v.Z - q.Z * v.Y);
        var ty = 2f * (q.Z * v.X - q.X * v.Z);
        var tz = 2f * (q.X * v.Y - q.Y * v.X);
        return new Vector3(
            v.X + q.W * tx + (q.Y * tz - q.Z * ty),
            v.Y + q.W * ty + (q.Z * tx - q.X * tz),
            v.Z + q.W * tz + (q.X * ty - q.Y * tx));
    }

    /// <summary>Rotation by the inverse of a unit quaternion (its conjugate).</summary>
    public static Vector3 RotateInverse(Quaternion q, Vector3 v) => Rotate(new Quaternion(-q.X, -q.Y, -q.Z, q.W), v);
}
