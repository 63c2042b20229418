using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// One of an EnvCell's portals: the polygon (an id into its CellStruct's drawing polygons, as ACE's
/// EnvCell looks it up) and the cell on the other side, a 16-bit id in the same landblock or
/// <see cref="Outside"/>. Eight bytes: flags, polygon id, other cell id, other portal id.
/// </summary>
public readonly record struct CellPortal(PortalFlags Flags, ushort PolygonId, ushort OtherCellId, ushort OtherPortalId)
{
    /// <summary>The other cell id of a portal that leads outdoors (ACE: OtherCellId == ushort.MaxValue).</summary>
    public const ushort Outside = 0xFFFF;

    public bool LeadsOutside => OtherCellId == Outside;

    public static CellPortal Read(DatBinaryReader r) => new((PortalFlags)r.ReadUInt16(), r.ReadUInt16(), r.ReadUInt16(), r.ReadUInt16());

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt16((ushort)Flags);
        w.WriteUInt16(PolygonId);
        w.WriteUInt16(OtherCellId);
        w.WriteUInt16(OtherPortalId);
    }
}
