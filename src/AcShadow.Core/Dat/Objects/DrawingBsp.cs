using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A drawing BSP, which collision never reads: stepped over node by node (it has no length prefix).
/// Layout (ACE's BSPNode/BSPLeaf/BSPPortal with BSPType.Drawing, DatReaderWriter's DrawingBSPNode):
/// a leaf is a tag and a leaf index; an internal node a tag, a plane, the children the tag names, a
/// sphere, a polygon count (uint) and the polygon ids (ushort each); a PORT node a tag, a plane, both
/// children, a sphere, a polygon count and a portal count (uint each), the polygon ids, then 4 bytes
/// per portal reference.
/// </summary>
public static class DrawingBsp
{
    public static void Skip(DatBinaryReader r, int depth = 0)
    {
        if (depth > 256) throw new DatFormatException("drawing BSP deeper than 256 levels");
        var type = (BspNodeType)r.ReadUInt32();
        if (type == BspNodeType.Leaf)
        {
            r.ReadInt32();
            return;
        }
        if (type == BspNodeType.Portal)
        {
            r.ReadPlane();
            Skip(r, depth + 1);
            Skip(r, depth + 1);
            r.Skip(16);
            var polygons = r.ReadCount(r.ReadUInt32(), 2, "drawing BSP polygon");
            var portals = r.ReadCount(r.ReadUInt32(), 4, "drawing BSP portal");
            r.Skip(polygons * 2);
            r.Skip(portals * 4);
            return;
        }
        if (!type.IsInternal()) throw new DatFormatException($"drawing BSP node tag 0x{(uint)type:X8} is not a BSP node type");
        r.ReadPlane();
        if (type.HasPos()) Skip(r, depth + 1);
        if (type.HasNeg()) Skip(r, depth + 1);
        r.Skip(16);
        r.Skip(r.ReadCount(r.ReadUInt32(), 2, "drawing BSP polygon") * 2);
    }

    /// <summary>The smallest drawing tree: one leaf (tag, leaf index 0).</summary>
    public static void WriteOneLeaf(DatBinaryWriter w)
    {
        w.WriteUInt32((uint)BspNodeType.Leaf);
        w.WriteInt32(0);
    }
}
