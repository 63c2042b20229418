using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Formats;

/// <summary>
/// A cell frame as 4×4 matrices in System.Numerics' convention, the one acdream's cell fixtures use
/// (row vectors, p' = p·M, so M = CreateFromQuaternion(q) · CreateTranslation(t), translation in
/// M41–M43). The rotation rows are the client's own matrix, m_fl2gv as Frame::cache builds it from the stored
/// quaternion (<see cref="ClientFrameMatrix"/>; its rows are M's rows), so a consumer multiplying by M uses the
/// client's entries. The inverse is the rigid inverse: the rotation transposed, translation −t·Rᵀ (a matrix
/// cannot subtract the origin first as Frame::globaltolocal does; docs/chart.md has the size of that).
/// </summary>
public static class CellMatrices
{
    public static Matrix4x4 World(Frame frame)
    {
        var m = ClientFrameMatrix.From(frame);
        var t = frame.Position;
        return new Matrix4x4(
            m.M0, m.M1, m.M2, 0f,
            m.M3, m.M4, m.M5, 0f,
            m.M6, m.M7, m.M8, 0f,
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
