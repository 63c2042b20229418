using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A PhysicsBSP node. Internal nodes: splitting plane, children as the tag says, bounding sphere.
/// Leaves: leaf index, solid flag, bounding sphere, polygon ids. Physics trees carry no portal nodes.
/// </summary>
public sealed record PhysicsBspNode(
    BspNodeType Type,
    Plane SplittingPlane,
    PhysicsBspNode? Pos,
    PhysicsBspNode? Neg,
    Sphere BoundingSphere,
    int LeafIndex,
    int Solid,
    IReadOnlyList<ushort> Polygons)
{
    public bool IsLeaf => Type == BspNodeType.Leaf;

    public static PhysicsBspNode Read(DatBinaryReader r, int depth = 0)
    {
        if (depth > 256) throw new DatFormatException("PhysicsBSP deeper than 256 levels");
        var type = (BspNodeType)r.ReadUInt32();
        if (type == BspNodeType.Leaf)
        {
            var leafIndex = r.ReadInt32();
            var solid = r.ReadInt32();
            var sphere = Sphere.Read(r);
            var count = r.ReadCount(r.ReadUInt32(), 2, "leaf polygon");
            var polys = new ushort[count];
            for (var i = 0; i < count; i++) polys[i] = r.ReadUInt16();
            return new PhysicsBspNode(type, default, null, null, sphere, leafIndex, solid, polys);
        }
        if (!type.IsInternal())
            throw new DatFormatException($"PhysicsBSP node tag 0x{(uint)type:X8} is not a physics node type");
        var plane = r.ReadPlane();
        var pos = type.HasPos() ? Read(r, depth + 1) : null;
        var neg = type.HasNeg() ? Read(r, depth + 1) : null;
        var bounds = Sphere.Read(r);
        return new PhysicsBspNode(type, plane, pos, neg, bounds, 0, 0, []);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)Type);
        if (IsLeaf)
        {
            w.WriteInt32(LeafIndex);
            w.WriteInt32(Solid);
            BoundingSphere.Write(w);
            w.WriteUInt32((uint)Polygons.Count);
            foreach (var p in Polygons) w.WriteUInt16(p);
            return;
        }
        w.WritePlane(SplittingPlane);
        Pos?.Write(w);
        Neg?.Write(w);
        BoundingSphere.Write(w);
    }
}
