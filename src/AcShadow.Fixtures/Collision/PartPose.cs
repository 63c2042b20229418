using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>A posed part: where its GfxObj sits in entity space, how it is turned, its uniform scale.</summary>
internal readonly record struct PartPose(Vector3 Position, Quaternion Rotation, float Scale)
{
    /// <summary>
    /// A part as CPartArray::UpdateParts places it in an entity at the identity frame: Frame::combine keeps the
    /// origin and normalises the rotation by Frame::set_rotate, so a part's frame never holds the animation's
    /// stored quaternion (the stored one stays when set_rotate refuses it).
    /// </summary>
    public static PartPose InEntity(Vector3 position, Quaternion rotation, float scale) =>
        new(position, ClientFrameMatrix.SetRotate(rotation) ?? rotation, scale);

    /// <summary>The part's frame as the client moves points with it (Frame::cache from the quaternion it holds).</summary>
    public ClientFrameMatrix Matrix => ClientFrameMatrix.From(new Frame(Position, Rotation));

    /// <summary>
    /// The query sphere in the part's own space (SPHEREPATH::cache_localspace_sphere): Frame::globaltolocal
    /// into the part's frame, then each stored component and the radius multiplied by the float 1 / scale.
    /// </summary>
    public (Vector3 Center, float Radius) ToLocal(Vector3 center, float radius) => ToLocal(Matrix, center, radius);

    /// <summary><see cref="ToLocal(Vector3, float)"/> with <see cref="Matrix"/> built once by a query asked many times.</summary>
    public (Vector3 Center, float Radius) ToLocal(in ClientFrameMatrix matrix, Vector3 center, float radius)
    {
        var invScale = 1f / Scale;
        var local = matrix.GlobalToLocal(center);
        return (new Vector3(local.X * invScale, local.Y * invScale, local.Z * invScale), radius * invScale);
    }

    /// <summary>A part-local point back in entity space: scaled, then Frame::localtoglobal.</summary>
    public Vector3 ToEntity(Vector3 local) =>
        Matrix.LocalToGlobal(new Vector3(local.X * Scale, local.Y * Scale, local.Z * Scale));
}
