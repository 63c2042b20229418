using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One placed object the mover walks against: its shadow shapes in entity space (BSP parts in their pose,
/// else CylSpheres, else Spheres: one family, as CPhysicsObj::FindObjCollisions picks it), the PhysicsBSPs its
/// parts name (compiled once here), where it stands (landblock-local frame), its scale and whether it is
/// ethereal. It is treated as a dynamic, non-creature object (a door): not Static, so an ethereal one never blocks.
/// </summary>
public sealed class MovementObject
{
    /// <summary>An object from its shadow shapes and the BSP dumps (gfxobjs/*.bsp.json) they name, by GfxObj id.</summary>
    public MovementObject(IReadOnlyList<ShadowShape> shapes, IReadOnlyDictionary<uint, BspDump> bsps, Vector3 position, Quaternion rotation,
        float scale = 1f, bool ethereal = false)
        : this(shapes, bsps.ToDictionary(b => b.Key, b => CompiledBsp.Compile(b.Value)), position, rotation, scale, ethereal)
    {
    }

    internal MovementObject(IReadOnlyList<ShadowShape> shapes, IReadOnlyDictionary<uint, CompiledBsp> bsps, Vector3 position, Quaternion rotation,
        float scale = 1f, bool ethereal = false)
    {
        Shapes = shapes;
        Bsps = bsps;
        Position = position;
        Rotation = rotation;
        Scale = scale;
        Ethereal = ethereal;
    }

    public IReadOnlyList<ShadowShape> Shapes { get; }
    internal IReadOnlyDictionary<uint, CompiledBsp> Bsps { get; }
    public Vector3 Position { get; }
    public Quaternion Rotation { get; }
    public float Scale { get; }
    public bool Ethereal { get; }
}
