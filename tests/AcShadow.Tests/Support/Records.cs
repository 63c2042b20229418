using System.Numerics;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Tests.Support;

/// <summary>Small in-memory Setups and GfxObjs for builder cases the dat format cannot express.</summary>
public static class Records
{
    public static GfxObj BoxGfxObj(uint id, float half = 0.5f, bool physics = true)
    {
        var vertices = new Dictionary<ushort, Vector3>
        {
            [0] = new(-half, -half, 0), [1] = new(half, -half, 0), [2] = new(half, half, 0), [3] = new(-half, half, 0),
        };
        var quad = new Polygon(Stippling.NoPos, SidesType.Clockwise, 0, 0, [0, 1, 2, 3], [], []);
        var leaf = new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(new Vector3(0, 0, 0), half * 1.5f), 0, 1, [0]);
        return new GfxObj(id, physics ? GfxObjFlags.HasPhysics : GfxObjFlags.HasDrawing, [], vertices,
            physics ? [new(0, quad)] : [], physics ? leaf : null, Vector3.Zero, physics ? [] : [new(0, quad)]);
    }

    public static Setup Setup(
        uint id,
        uint[] parts,
        PlacementFrame[]? placements = null,
        CylSphere[]? cyls = null,
        Sphere[]? spheres = null,
        Vector3[]? defaultScale = null,
        SetupFlags flags = SetupFlags.None,
        float radius = 0.5f,
        float height = 1f) =>
        new(id, flags, parts, [], defaultScale ?? [], placements ?? [], cyls ?? [], spheres ?? [], height, radius, 0, 0, default, default);

    public static PlacementFrame PlacementAt(uint key, params Vector3[] origins) =>
        new(key, origins.Select(o => new Frame(o, Quaternion.Identity)).ToArray());

    public static Func<uint, GfxObj?> Lookup(params GfxObj[] objects) => id => objects.FirstOrDefault(o => o.Id == id);
}
