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

    /// <summary>
    /// Frame::IsValid's test of a quaternion: the float sum of squares (z, y, x, w in that order) within
    /// 0.0002 * 5 of 1, no NaN. Frame::UnPack keeps a quaternion that passes as read; Frame::set_rotate keeps
    /// its old one when the normalised one fails.
    /// </summary>
    public static bool IsValid(Quaternion q)
    {
        var norm = (float)((double)q.Z * q.Z + (double)q.Y * q.Y + (double)q.X * q.X + (double)q.W * q.W);
        return !float.IsNaN(norm) && !(Math.Abs(norm - 1.0) > (double)0.0002f * 5.0);
    }

    /// <summary>
    /// Frame::set_rotate: 1 / sqrt(w² + x² + y² + z²) held unrounded, each component times it stored as a float;
    /// null when the result fails <see cref="IsValid"/> (the client then keeps the frame's old rotation).
    /// </summary>
    public static Quaternion? SetRotate(Quaternion q)
    {
        double w = q.W, x = q.X, y = q.Y, z = q.Z;
        var inverse = 1.0 / Math.Sqrt(w * w + x * x + y * y + z * z);
        var normalised = new Quaternion((float)(x * inverse), (float)(y * inverse), (float)(inverse * z), (float)(w * inverse));
        return IsValid(normalised) ? normalised : null;
    }

    /// <summary>
    /// The rotation a placed frame (a landblock stab, a building, a cell, an object placed by the consumer) holds:
    /// the stored quaternion when <see cref="IsValid"/> accepts it, as Frame::UnPack and CPhysicsObj::set_initial_frame
    /// and add_obj_to_cell keep it (no normalisation); else, where the client would refuse the frame, the
    /// quaternion normalised as Frame::set_rotate does; identity when even that fails (zero, NaN, infinity).
    /// </summary>
    public static Quaternion PlacedRotation(Quaternion stored) =>
        IsValid(stored) ? stored : SetRotate(stored) ?? Quaternion.Identity;

    /// <summary>
    /// Frame::combine(f1, AFrame f2, scale), as CPartArray::UpdateParts places a part in its object's frame:
    /// f2's origin times the scale held unrounded, through f1's matrix x term first, then z, then y, then f1's
    /// origin; the quaternion product f1·f2 in the client's order of terms, each component stored as a float,
    /// then <see cref="SetRotate"/> (a product that fails it keeps the unnormalised product: the client would keep
    /// the part's previous rotation, which a pose built once does not have).
    /// </summary>
    public static Frame Combine(Frame outer, Frame inner, float scale)
    {
        var m = From(outer);
        double sx = (double)inner.Position.X * scale, sy = (double)inner.Position.Y * scale, sz = (double)inner.Position.Z * scale;
        var origin = new Vector3(
            (float)(sx * m.M0 + sz * m.M6 + sy * m.M3 + outer.Position.X),
            (float)(sx * m.M1 + sz * m.M7 + sy * m.M4 + outer.Position.Y),
            (float)(sx * m.M2 + sz * m.M8 + sy * m.M5 + outer.Position.Z));
        double ow = outer.Rotation.W, ox = outer.Rotation.X, oy = outer.Rotation.Y, oz = outer.Rotation.Z;
        double iw = inner.Rotation.W, ix = inner.Rotation.X, iy = inner.Rotation.Y, iz = inner.Rotation.Z;
        var product = new Quaternion(
            (float)(ix * ow + iw * ox + iz * oy - iy * oz),
            (float)(ow * iy - ox * iz + ix * oz + iw * oy),
            (float)(ow * iz + ox * iy - ix * oy + iw * oz),
            (float)(iw * ow - ix * ox - iy * oy - iz * oz));
        return new Frame(origin, SetRotate(product) ?? product);
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

    /// <summary>Frame::localtoglobalvec: a direction by the matrix alone, z term first, then x, then y.</summary>
    public Vector3 LocalToGlobalVec(Vector3 local)
    {
        double x = local.X, y = local.Y, z = local.Z;
        return new Vector3(
            (float)((double)M6 * z + (double)M0 * x + (double)M3 * y),
            (float)((double)M7 * z + (double)M1 * x + (double)M4 * y),
            (float)((double)M8 * z + (double)M2 * x + (double)M5 * y));
    }

    /// <summary>
    /// The local up direction SPHEREPATH::cache_localspace_sphere derives, (m1 + m0)·0 + m2 and the same for the other
    /// two rows: the global z axis in the frame (the transpose's third column), zero signs as the client forms them.
    /// </summary>
    public Vector3 LocalUp() => new(
        (float)(((double)M1 + M0) * 0.0 + M2),
        (float)(((double)M4 + M3) * 0.0 + M5),
        (float)(((double)M7 + M6) * 0.0 + M8));

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
