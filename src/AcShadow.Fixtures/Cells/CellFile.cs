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
