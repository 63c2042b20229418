using System.Numerics;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A node of a CellStruct's cell BSP (the tree that says whether a point is inside the cell). Cell
/// trees store less than physics ones (ACE's BSPNode.Unpack with BSPType.Cell, DatReaderWriter's
/// CellBSPNode): internal nodes a tag, a splitting plane and the children the tag names, no sphere;
/// leaves a tag and a leaf index. A PORT node (which DatReaderWriter refuses in cell trees) is read as
/// ACE reads it: a plane and both children.
/// </summary>
public sealed record CellBspNode(BspNodeType Type, Plane SplittingPlane, CellBspNode? Pos, CellBspNode? Neg, int LeafIndex)
{
    public bool IsLeaf => Type == BspNodeType.Leaf;

    public static CellBspNode Read(DatBinaryReader r, int depth = 0)
    {
        if (depth > 256) throw new DatFormatException("cell BSP deeper than 256 levels");
        var type = (BspNodeType)r.ReadUInt32();
        if (type == BspNodeType.Leaf) return new CellBspNode(type, default, null, null, r.ReadInt32());
        var portal = type == BspNodeType.Portal;
        if (!portal && !type.IsInternal())
            throw new DatFormatException($"cell BSP node tag 0x{(uint)type:X8} is not a BSP node type");
        var plane = r.ReadPlane();
        var pos = portal || type.HasPos() ? Read(r, depth + 1) : null;
        var neg = portal || type.HasNeg() ? Read(r, depth + 1) : null;
        return new CellBspNode(type, plane, pos, neg, 0);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)Type);
        if (IsLeaf)
        {
            w.WriteInt32(LeafIndex);
            return;
        }
        w.WritePlane(SplittingPlane);
        Pos?.Write(w);
        Neg?.Write(w);
    }
}
