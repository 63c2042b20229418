using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Analysis.View;

/// <summary>Where an object stands in a view: position, then a unit rotation (dat axes).</summary>
public readonly record struct ViewFrame(Vector3 Position, Quaternion Rotation)
{
    public static ViewFrame Identity { get; } = new(Vector3.Zero, Quaternion.Identity);

    public Vector3 Apply(Vector3 local)
    {
        var turned = QuaternionRotation.Rotate(Rotation, local);
        return new Vector3(turned.X + Position.X, turned.Y + Position.Y, turned.Z + Position.Z);
    }
}
