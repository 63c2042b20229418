using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Collision;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Movement;

/// <summary>
/// Movers, walks and objects for the hand-worked movement cases: one-part objects made from test meshes
/// through the real BSP path (TestGfx → BspExtractor → CompiledBsp), and the forged sample door.
/// </summary>
public static class MovementScenes
{
    /// <summary>holtburger's human: spheres (0,0,0.475) and (0,0,1.35), r 0.48; step up 0.6, down 1.5.</summary>
    public static Mover Human(bool edgeSlide = true) =>
        new([new Sphere(new Vector3(0f, 0f, 0.475f), 0.48f), new Sphere(new Vector3(0f, 0f, 1.35f), 0.48f)], 0.6f, 1.5f) { EdgeSlide = edgeSlide };

    /// <summary>Sphere 0's bottom (0.475 − 0.48) is 5 mm under the origin: standing on z, the origin is at z + 0.005.</summary>
    public const float StandingLift = 0.005f;

    public const float WalkSpeed = 3.12f;

    public static MovementObject OnePart(TestMesh mesh, Vector3 position, Quaternion rotation, uint id = 0x01009000, bool ethereal = false)
    {
        var bsp = CompiledBsp.Compile(TestGfx.Dump(id, mesh));
        var shape = new ShadowShape(ShapeSource.Part, 0, id, CollisionType.Bsp, Vector3.Zero, Quaternion.Identity, 1f, bsp.Nodes[0].SphereRadius, 0f, null);
        return new MovementObject([shape], new Dictionary<uint, CompiledBsp> { [id] = bsp }, position, rotation, 1f, ethereal);
    }

    /// <summary>A box from <paramref name="min"/> to <paramref name="max"/> as a one-part object at the origin.</summary>
    public static MovementObject Block(Vector3 min, Vector3 max, bool ethereal = false) =>
        OnePart(TestMesh.Box((min + max) * 0.5f, (max - min) * 0.5f), Vector3.Zero, Quaternion.Identity, ethereal: ethereal);

    public const uint Door = 0x020019FF;

    /// <summary>The sample door's retail shapes (posed closed or open) and its parts' BSPs, standing at the origin.</summary>
    public static (MovementObject Door, ShadowShapeSet Set) SampleDoor(DoorState state)
    {
        using var dat = SampleDat.OpenPortal();
        var set = ShadowShapeBuilder.Build(dat.ReadSetup(Door)!, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail) { DoorState = state }, dat);
        var bsps = new Dictionary<uint, CompiledBsp>();
        foreach (var id in set.Shapes.Where(s => s.GfxObjId is not null).Select(s => s.GfxObjId!.Value).Distinct())
            bsps[id] = CompiledBsp.Compile(BspExtractor.Extract(dat.ReadGfxObj(id)!)!);
        return (new MovementObject(set.Shapes, bsps, Vector3.Zero, Quaternion.Identity, 1f, set.Pose.Ethereal), set);
    }

    /// <summary>The door's first Setup sphere as the buggy client's one cylinder: base at the sphere's centre, height 2r.</summary>
    public static MovementObject SampleDoorCircle()
    {
        using var dat = SampleDat.OpenPortal();
        var sphere = dat.ReadSetup(Door)!.Spheres[0];
        var shape = new ShadowShape(ShapeSource.Sphere, 0, null, CollisionType.Cylinder, sphere.Center, Quaternion.Identity, 1f, sphere.Radius, 2f * sphere.Radius, null);
        return new MovementObject([shape], new Dictionary<uint, CompiledBsp>(), Vector3.Zero, Quaternion.Identity);
    }

    /// <summary>A walk along +y at walking speed from (x, y) standing on the floor at z 0, 30 frames a second.</summary>
    public static Walk WalkNorth(float x, float y, int frames, float speed = WalkSpeed) =>
        new(new Vector3(x, y, StandingLift), new Vector3(0f, speed, 0f), 0f, frames);
}
