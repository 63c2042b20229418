using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Cells;

/// <summary>
/// A cell file read back: an indoor cell's frame (landblock-relative, and its world origin), its
/// physics polygons and PhysicsBSP in the cell's own frame, its portals, the cells it sees and the
/// objects placed inside it.
/// </summary>
public sealed record CellFile(
    uint CellId,
    uint EnvironmentId,
    int CellStructure,
    uint Flags,
    bool SeenOutside,
    Vector3 LandblockOrigin,
    Quaternion Orientation,
    Vector3 WorldOrigin,
    BspDump Physics,
    IReadOnlyList<CellPortalRecord> Portals,
    IReadOnlyList<uint> VisibleCells,
    IReadOnlyList<CellObject> Objects)
{
    /// <summary>The LandBlockInfo id of the cell's landblock (0xXXYYFFFE).</summary>
    public uint LandblockId => (CellId & 0xFFFF0000u) | 0xFFFE;
}

/// <summary>
/// One portal: the dat's flags, its polygon (a drawing polygon of the cell structure, in the cell's
/// frame, with its retail plane; null plane when degenerate), and the other side: a cell of the same
/// landblock, or outdoors (<see cref="OtherCellId"/> then ends in 0xFFFF).
/// </summary>
public sealed record CellPortalRecord(int Index, ushort Flags, ushort PolygonId, uint OtherCellId, ushort OtherPortalId,
    IReadOnlyList<Vector3> Vertices, Plane? Plane)
{
    public bool LeadsOutside => (OtherCellId & 0xFFFF) == CellFileFormat.Outside;
}

/// <summary>
/// An object placed inside a cell (the EnvCell's stabs): its landblock-relative frame, its world origin,
/// and the file that describes it (a Setup's shadow file, or a bare GfxObj's BSP dump with its one shape).
/// </summary>
public sealed record CellObject(int Index, uint Id, string Kind, Vector3 LandblockPosition, Quaternion Rotation, Vector3 WorldPosition,
    string? File, IReadOnlyList<ShadowShape> Shapes);
