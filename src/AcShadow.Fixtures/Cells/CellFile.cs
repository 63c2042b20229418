using System.Numerics;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Cells;

/// <summary>
/// A cell file read back: an indoor cell's frames (landblock-relative and world), its
/// physics polygons and PhysicsBSP in the cell's own frame, its portals, the cells it sees and the
/// objects placed inside it.
/// </summary>
public sealed record CellFile(
    uint CellId,
    uint EnvironmentId,
    int CellStructure,
    uint Flags,
    bool SeenOutside,
    Frame LandblockFrame,
    Frame WorldFrame,
    BspDump Physics,
    IReadOnlyList<CellPortalRecord> Portals,
    IReadOnlyList<uint> VisibleCells,
    IReadOnlyList<PlacedObject> Objects)
{
    /// <summary>The LandBlockInfo id of the cell's landblock (0xXXYYFFFE).</summary>
    public uint LandblockId => (CellId & 0xFFFF0000u) | 0xFFFE;
}
