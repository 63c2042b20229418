using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>A posed part: where its GfxObj sits in entity space, how it is turned, its uniform scale.</summary>
internal readonly record struct PartPose(Vector3 Position, Quaternion Rotation, float Scale)
{
    /// <summary>
    /// The query sphere in the part's own space (CSpherePath::CacheLocalSpaceSphere): offset from the part,
    /// turned by the inverse rotation, then multiplied by 1 / scale, centre and radius alike.
    /// </summary>
    public (Vector3 Center, float Radius) ToLocal(Vector3 center, float radius)
    {
        var invScale = 1f / Scale;
        var local = QuaternionRotation.RotateInverse(Rotation, Vec.Sub(center, Position));
        return (new Vector3(local.X * invScale, local.Y * invScale, local.Z * invScale), radius * invScale);
    }

    /// <summary>A part-local point back in entity space.</summary>
    public Vector3 ToEntity(Vector3 local)
    {
        var scaled = new Vector3(local.X * Scale, local.Y * Scale, local.Z * Scale);
        var turned = QuaternionRotation.Rotate(Rotation, scaled);
        return new Vector3(turned.X + Position.X, turned.Y + Position.Y, turned.Z + Position.Z);
    }
}
