using System.Numerics;

namespace AcShadow.Fixtures.Geometry;

/// <summary>
/// Where something stands in an outer frame: its position, then its rotation (a quaternion, dat axes). The
/// dat's Frame (origin, then orientation stored W, X, Y, Z), a placed object's landblock or world frame, a
/// cell's frame and a view's are all this.
/// </summary>
public readonly record struct Frame(Vector3 Position, Quaternion Rotation)
{
    public static Frame Identity { get; } = new(Vector3.Zero, Quaternion.Identity);

    /// <summary>
    /// A point of this frame in the outer one, as the client moves it (Frame::localtoglobal by the matrix
    /// Frame::cache builds from the stored quaternion, <see cref="ClientFrameMatrix"/>).
    /// </summary>
    internal Vector3 Apply(Vector3 local) => ClientFrameMatrix.From(this).LocalToGlobal(local);
}
