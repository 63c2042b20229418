using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// Real-format dats holding objects the forge's spec validator would refuse, written with the object
/// writers and <see cref="DatArchiveWriter"/> (or, where the format cannot express the fault, as raw bytes)
/// and read back through the real reader.
/// </summary>
public static class BrokenDats
{
    /// <summary>A healthy one-part Setup whose part is a box with a PhysicsBSP: the "rest of the batch".</summary>
    public const uint HealthySetup = 0x02000001;
    public const uint HealthyGfxObj = 0x01000001;

    public static byte[] Portal(params (uint Id, byte[] Bytes)[] objects) =>
        Archive(DatFileKind.Portal, objects.Concat(Healthy()).ToArray());

    public static byte[] Archive(DatFileKind kind, params (uint Id, byte[] Bytes)[] objects) =>
        DatArchiveWriter.Write(objects.ToDictionary(o => o.Id, o => o.Bytes), new DatArchiveWriter.Options(kind));

    /// <summary>Writes the portal dat as client_portal.dat in a new folder and returns the folder.</summary>
    public static TempDir Folder(byte[] portal)
    {
        var dir = new TempDir();
        File.WriteAllBytes(Path.Combine(dir.Path, "client_portal.dat"), portal);
        return dir;
    }

    public static (uint, byte[]) Bytes(Setup setup)
    {
        var w = new DatBinaryWriter();
        setup.Write(w);
        return (setup.Id, w.ToArray());
    }

    public static (uint, byte[]) Bytes(GfxObj gfx)
    {
        var w = new DatBinaryWriter();
        gfx.Write(w);
        return (gfx.Id, w.ToArray());
    }

    /// <summary>A Setup of <paramref name="parts"/> placed by a Resting frame, one frame per part side by side.</summary>
    public static Setup SetupOf(uint id, params uint[] parts) =>
        Records.Setup(id, parts, [Records.PlacementAt(Placement.Resting, parts.Select((_, i) => new Vector3(i * 2f, 0, 0)).ToArray())],
            flags: SetupFlags.HasPhysicsBsp);

    /// <summary>A box GfxObj with one physics polygon; <paramref name="bsp"/> replaces its one-leaf tree.</summary>
    public static GfxObj Box(uint id, Func<Dictionary<ushort, Vector3>, Dictionary<ushort, Vector3>>? vertices = null,
        short[]? polygonVertices = null, PhysicsBspNode? bsp = null)
    {
        var box = Records.BoxGfxObj(id);
        var verts = vertices?.Invoke(box.Vertices.ToDictionary()) ?? box.Vertices.ToDictionary();
        var polygon = box.PhysicsPolygons[0].Value with { VertexIds = polygonVertices ?? [0, 1, 2, 3] };
        return box with { Vertices = verts, PhysicsPolygons = [new(0, polygon)], PhysicsBsp = bsp ?? box.PhysicsBsp };
    }

    /// <summary>A chain of internal nodes <paramref name="depth"/> deep ending in a solid leaf holding polygon 0.</summary>
    public static PhysicsBspNode Chain(int depth)
    {
        var node = new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 1f), 0, 1, [0]);
        for (var i = 0; i < depth; i++)
            node = new PhysicsBspNode(BspNodeType.BPIn, new Plane(Vector3.UnitX, -i), node, null, new Sphere(Vector3.Zero, 1f), 0, 0, []);
        return node;
    }

    private static IEnumerable<(uint, byte[])> Healthy() =>
        [Bytes(SetupOf(HealthySetup, HealthyGfxObj)), Bytes(Box(HealthyGfxObj))];
}
