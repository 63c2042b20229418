using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Shapes;

/// <summary>
/// One collision-bearing shape of an entity, in the entity's local frame.
/// BSP shapes: the part's GfxObj, pose and uniform scale, <see cref="Radius"/> = the BSP root sphere's
/// radius × scale, <see cref="LocalSphere"/> = that sphere in entity space. Cylinder shapes: base centre,
/// radius and <see cref="CylHeight"/>. Sphere shapes: centre and radius.
/// </summary>
public sealed record ShadowShape(
    ShapeSource Source,
    int SourceIndex,
    uint? GfxObjId,
    CollisionType CollisionType,
    Vector3 LocalPosition,
    Quaternion LocalRotation,
    float Scale,
    float Radius,
    float CylHeight,
    Sphere? LocalSphere);
