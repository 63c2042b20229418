using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// The few vector operations the transition needs beyond <see cref="Vec"/>, in scalar float arithmetic in a
/// fixed order (no SIMD dot products), so a walk gives the same bits on every machine.
/// </summary>
internal static class MoveMath
{
    public static float Dot(Vector3 a, Vector3 b) => PolygonPlane.Dot(a, b);

    public static float LengthSquared(Vector3 v) => v.X * v.X + v.Y * v.Y + v.Z * v.Z;

    public static float LengthSquared2D(Vector3 v) => v.X * v.X + v.Y * v.Y;

    public static Vector3 Scale(Vector3 v, float s) => new(v.X * s, v.Y * s, v.Z * s);

    /// <summary>
    /// Vector3::normalize_check_small: true (and <paramref name="v"/> untouched) when its length is below ε,
    /// else <paramref name="v"/> is scaled by 1 / length.
    /// </summary>
    public static bool NormalizeCheckSmall(ref Vector3 v)
    {
        var length = MathF.Sqrt(LengthSquared(v));
        if (length < MovementConstants.Epsilon) return true;
        v = Scale(v, 1f / length);
        return false;
    }
}
