using System.Numerics;

namespace AcShadow.Fixtures.Geometry;

/// <summary>
/// A frame as the retail client moves points with it: the 3x3 matrix <c>m_fl2gv</c> that Frame::cache builds
/// from the stored quaternion (not normalised: the dat's 0.70710677 is kept as read), local-to-global by the
/// matrix (Frame::localtoglobal) and global-to-local by its transpose (Frame::globaltolocal), each sum in the
/// client's order of terms.
/// </summary>
/// <remarks>
/// The client computes on the x87 with precision control set to 53 bits and round-to-nearest
/// (ClientMain::ConfigureFPU; Direct3D is created with FPU_PRESERVE), so every x87 operation rounds exactly as an
/// IEEE double operation does, and every store to a float rounds once. Each expression here is therefore
/// evaluated in double and rounded to float exactly where the client stores a float; for finite float inputs
/// this is bit for bit (the x87's wider exponent range only matters below 1e-300, which products of floats
/// never reach). docs/chart.md has the measured difference from the older normalise-then-rotate arithmetic.
/// </remarks>
internal readonly record struct ClientFrameMatrix(
    Vector3 Origin, float M0, float M1, float M2, float M3, float M4, float M5, float M6, float M7, float M8)
{
    /// <summary>Frame::cache: b2 = 2qx, c2 = 2qy, d2 = 2qz held unrounded, the nine entries stored as floats.</summary>
    public static ClientFrameMatrix From(Frame frame)
    {
        double qw = frame.Rotation.W, qx = frame.Rotation.X, qy = frame.Rotation.Y, qz = frame.Rotation.Z;
        double b2 = qx + qx, c2 = qy + qy, d2 = qz + qz;
        double wb = qw * b2, wc = qw * c2, wd = qw * d2;
        double xb = qx * b2, xc = qx * c2, xd = qx * d2;
        double yc = qy * c2, yd = qy * d2, zd = qz * d2;
        var oneMinusXb = 1.0 - xb;
        return new ClientFrameMatrix(frame.Position,
            (float)(1.0 - yc - zd), (float)(xc + wd), (float)(xd - wc),
            (float)(xc - wd), (float)(oneMinusXb - zd), (float)(yd + wb),
            (float)(xd + wc), (float)(yd - wb), (float)(oneMinusXb - yc));
    }

    /// <summary>Frame::localtoglobal: each axis sums its z term, then x, then y, then the origin.</summary>
    public Vector3 LocalToGlobal(Vector3 local)
    {
        double x = local.X, y = local.Y, z = local.Z;
        return new Vector3(
            (float)((double)M6 * z + (double)M0 * x + (double)M3 * y + Origin.X),
            (float)((double)M7 * z + (double)M1 * x + (double)M4 * y + Origin.Y),
            (float)((double)M8 * z + (double)M2 * x + (double)M5 * y + Origin.Z));
    }

    /// <summary>
    /// Frame::globaltolocal: the offset from the origin stored as floats, except that the result's z uses the
    /// unrounded z offset still on the x87 stack; then the transpose, z term first.
    /// </summary>
    public Vector3 GlobalToLocal(Vector3 global)
    {
        var dx = (float)((double)global.X - Origin.X);
        var dy = (float)((double)global.Y - Origin.Y);
        var dzHeld = (double)global.Z - Origin.Z;
        double dzStored = (float)dzHeld;
        return new Vector3(
            (float)(dzStored * M2 + (double)dx * M0 + (double)dy * M1),
            (float)(dzStored * M5 + (double)dx * M3 + (double)dy * M4),
            (float)(dzHeld * M8 + (double)dx * M6 + (double)dy * M7));
    }
}
