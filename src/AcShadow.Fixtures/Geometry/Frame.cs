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

    /// <summary>A point of this frame in the outer one: turned by <see cref="Rotation"/> (a unit quaternion), then offset.</summary>
    internal Vector3 Apply(Vector3 local)
    {
        var turned = QuaternionRotation.Rotate(Rotation, local);
        return new Vector3(turned.X + Position.X, turned.Y + Position.Y, turned.Z + Position.Z);
    }
}
