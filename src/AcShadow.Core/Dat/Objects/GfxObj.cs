using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A GfxObj (0x01xxxxxx): vertices, and when <see cref="GfxObjFlags.HasPhysics"/> is set the physics
/// polygons and PhysicsBSP. Decoding stops after the sort centre: drawing polygons and the drawing BSP
/// play no part in collision, so they are not read. Writing emits them when given (the forge's
/// drawing-only objects) with a one-leaf drawing BSP.
/// </summary>
public sealed record GfxObj(
    uint Id,
    GfxObjFlags Flags,
    IReadOnlyList<uint> Surfaces,
    IReadOnlyDictionary<ushort, Vector3> Vertices,
    IReadOnlyList<KeyValuePair<ushort, Polygon>> PhysicsPolygons,
    PhysicsBspNode? PhysicsBsp,
    Vector3 SortCenter,
    IReadOnlyList<KeyValuePair<ushort, Polygon>> DrawingPolygons)
{
    public bool HasPhysics => Flags.HasFlag(GfxObjFlags.HasPhysics) && PhysicsBsp is not null;

    public static GfxObj Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var flags = (GfxObjFlags)r.ReadUInt32();
        var surfaceCount = r.ReadCount(r.ReadCompressedUInt32(), 4, "surface");
        var surfaces = new uint[surfaceCount];
        for (var i = 0; i < surfaceCount; i++) surfaces[i] = r.ReadUInt32();

        var vertices = VertexArrayLayout.Read(r);

        List<KeyValuePair<ushort, Polygon>> physicsPolygons = [];
        PhysicsBspNode? bsp = null;
        if (flags.HasFlag(GfxObjFlags.HasPhysics))
        {
            var polyCount = r.ReadCount(r.ReadCompressedUInt32(), 12, "physics polygon");
            physicsPolygons = new(polyCount);
            for (var i = 0; i < polyCount; i++)
            {
                var key = r.ReadUInt16();
                physicsPolygons.Add(new(key, Polygon.Read(r)));
            }
            bsp = PhysicsBspNode.Read(r);
        }
        var sortCenter = r.ReadVector3();
        return new GfxObj(id, flags, surfaces, vertices, physicsPolygons, bsp, sortCenter, []);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        w.WriteUInt32((uint)Flags);
        w.WriteCompressedUInt32((uint)Surfaces.Count);
        foreach (var s in Surfaces) w.WriteUInt32(s);
        VertexArrayLayout.Write(w, Vertices);
        if (Flags.HasFlag(GfxObjFlags.HasPhysics))
        {
            w.WriteCompressedUInt32((uint)PhysicsPolygons.Count);
            foreach (var (key, poly) in PhysicsPolygons)
            {
                w.WriteUInt16(key);
                poly.Write(w);
            }
            (PhysicsBsp ?? throw new InvalidOperationException($"GfxObj 0x{Id:X8} has the physics flag but no PhysicsBSP")).Write(w);
        }
        w.WriteVector3(SortCenter);
        if (Flags.HasFlag(GfxObjFlags.HasDrawing))
        {
            w.WriteCompressedUInt32((uint)DrawingPolygons.Count);
            foreach (var (key, poly) in DrawingPolygons)
            {
                w.WriteUInt16(key);
                poly.Write(w);
            }
            // One drawing leaf: tag, leaf index (drawing leaves carry nothing else).
            w.WriteUInt32((uint)BspNodeType.Leaf);
            w.WriteInt32(0);
        }
        if (Flags.HasFlag(GfxObjFlags.HasDIDDegrade)) w.WriteUInt32(0);
    }
}
