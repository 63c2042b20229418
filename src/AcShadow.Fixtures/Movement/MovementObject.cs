using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One placed object the mover walks against: its shadow shapes in entity space (BSP parts in their pose,
/// else CylSpheres, else Spheres: one family, as CPhysicsObj::FindObjCollisions picks it), the compiled
/// PhysicsBSPs its parts name, where it stands (landblock-local frame), its scale and whether it is ethereal.
/// It is treated as a dynamic, non-creature object (a door): not Static, so an ethereal one never blocks.
/// </summary>
public sealed record MovementObject(
    IReadOnlyList<ShadowShape> Shapes,
    IReadOnlyDictionary<uint, CompiledBsp> Bsps,
    Vector3 Position,
    Quaternion Rotation,
    float Scale = 1f,
    bool Ethereal = false);
