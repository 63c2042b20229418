using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Formats;

/// <summary>
/// A cell frame as 4×4 matrices in System.Numerics' convention, the one acdream's cell fixtures use
/// (row vectors, p' = p·M, so M = CreateFromQuaternion(q) · CreateTranslation(t), translation in
/// M41–M43). Written out in scalar float arithmetic in a fixed order so every machine gets the same bits.
/// The inverse is the rigid inverse: the rotation transposed, translation −t·Rᵀ.
/// </summary>
public static class CellMatrices
{
    public static Matrix4x4 World(Frame frame)
    {
        var q = frame.Rotation;
        float xx = q.X * q.X, yy = q.Y * q.Y, zz = q.Z * q.Z;
        float xy = q.X * q.Y, wz = q.Z * q.W, xz = q.Z * q.X, wy = q.Y * q.W, yz = q.Y * q.Z, wx = q.X * q.W;
        var t = frame.Position;
        return new Matrix4x4(
            1f - 2f * (yy + zz), 2f * (xy + wz), 2f * (xz - wy), 0f,
            2f * (xy - wz), 1f - 2f * (zz + xx), 2f * (yz + wx), 0f,
            2f * (xz + wy), 2f * (yz - wx), 1f - 2f * (yy + xx), 0f,
            t.X, t.Y, t.Z, 1f);
    }

    public static Matrix4x4 Inverse(Frame frame)
    {
        var m = World(frame);
        var t = frame.Position;
        return new Matrix4x4(
            m.M11, m.M21, m.M31, 0f,
            m.M12, m.M22, m.M32, 0f,
            m.M13, m.M23, m.M33, 0f,
            -(t.X * m.M11 + t.Y * m.M12 + t.Z * m.M13),
            -(t.X * m.M21 + t.Y * m.M22 + t.Z * m.M23),
            -(t.X * m.M31 + t.Y * m.M32 + t.Z * m.M33),
            1f);
    }
}
