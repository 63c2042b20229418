using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Geometry;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// An indoor cell (cell dat, 0xXXYY0100 and up): which CellStruct of which Environment it is, where it
/// sits (a landblock-relative frame, like a Stab's), its portals, the cells seen from it and the static
/// objects inside it. Layout (DatReaderWriter's dats.xml EnvCell, ACE's EnvCell.Unpack): id, flags, the
/// id again, surface count (byte), portal count (byte), visible cell count (ushort), surfaces (ushort
/// each), environment (ushort, the low half of 0x0D00XXXX), cell structure (ushort), frame, portals,
/// visible cells (ushort each), then the stabs (uint count) when HasStaticObjs and a uint when
/// HasRestrictionObj. No padding anywhere.
/// </summary>
public sealed record EnvCell(
    uint Id,
    EnvCellFlags Flags,
    IReadOnlyList<ushort> Surfaces,
    ushort EnvironmentId,
    ushort CellStructure,
    Frame Position,
    IReadOnlyList<CellPortal> Portals,
    IReadOnlyList<ushort> VisibleCells,
    IReadOnlyList<Stab> StaticObjects,
    uint RestrictionObj)
{
    /// <summary>The Environment's portal dat id (0x0D000000 | the stored 16 bits).</summary>
    public uint EnvironmentFileId => 0x0D000000u | EnvironmentId;

    public bool SeenOutside => Flags.HasFlag(EnvCellFlags.SeenOutside);

    /// <summary>The full id of a cell this one names by its low 16 bits (same landblock).</summary>
    public uint Sibling(ushort cellId) => (Id & 0xFFFF0000u) | cellId;

    public static EnvCell Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var flags = (EnvCellFlags)r.ReadUInt32();
        var again = r.ReadUInt32();
        if (again != id) throw new DatFormatException($"the cell id is stored twice, as 0x{id:X8} and 0x{again:X8}");
        var surfaceCount = r.ReadByte();
        var portalCount = r.ReadByte();
        var visibleCount = r.ReadUInt16();
        var surfaces = new ushort[r.ReadCount(surfaceCount, 2, "surface")];
        for (var i = 0; i < surfaces.Length; i++) surfaces[i] = r.ReadUInt16();
        var environment = r.ReadUInt16();
        var structure = r.ReadUInt16();
        var frame = r.ReadFrame();
        var portals = new CellPortal[r.ReadCount(portalCount, 8, "cell portal")];
        for (var i = 0; i < portals.Length; i++) portals[i] = CellPortal.Read(r);
        var visible = new ushort[r.ReadCount(visibleCount, 2, "visible cell")];
        for (var i = 0; i < visible.Length; i++) visible[i] = r.ReadUInt16();
        Stab[] stabs = [];
        if (flags.HasFlag(EnvCellFlags.HasStaticObjs))
        {
            stabs = new Stab[r.ReadCount(r.ReadUInt32(), 32, "static object")];
            for (var i = 0; i < stabs.Length; i++) stabs[i] = Stab.Read(r);
        }
        var restriction = flags.HasFlag(EnvCellFlags.HasRestrictionObj) ? r.ReadUInt32() : 0u;
        return new EnvCell(id, flags, surfaces, environment, structure, frame, portals, visible, stabs, restriction);
    }

    /// <summary>HasStaticObjs is written when there are stabs, whatever <see cref="Flags"/> says, so the bytes always parse.</summary>
    public void Write(DatBinaryWriter w)
    {
        if (Surfaces.Count > byte.MaxValue || Portals.Count > byte.MaxValue || VisibleCells.Count > ushort.MaxValue)
            throw new InvalidOperationException($"EnvCell 0x{Id:X8}: at most 255 surfaces, 255 portals and 65535 visible cells fit the dat");
        var flags = StaticObjects.Count > 0 ? Flags | EnvCellFlags.HasStaticObjs : Flags & ~EnvCellFlags.HasStaticObjs;
        w.WriteUInt32(Id);
        w.WriteUInt32((uint)flags);
        w.WriteUInt32(Id);
        w.WriteByte((byte)Surfaces.Count);
        w.WriteByte((byte)Portals.Count);
        w.WriteUInt16((ushort)VisibleCells.Count);
        foreach (var s in Surfaces) w.WriteUInt16(s);
        w.WriteUInt16(EnvironmentId);
        w.WriteUInt16(CellStructure);
        w.WriteFrame(Position);
        foreach (var p in Portals) p.Write(w);
        foreach (var v in VisibleCells) w.WriteUInt16(v);
        if (flags.HasFlag(EnvCellFlags.HasStaticObjs))
        {
            w.WriteUInt32((uint)StaticObjects.Count);
            foreach (var s in StaticObjects) s.Write(w);
        }
        if (flags.HasFlag(EnvCellFlags.HasRestrictionObj)) w.WriteUInt32(RestrictionObj);
    }
}
