using System.Numerics;

namespace AcShadow.Fixtures.Cells;

/// <summary>
/// One portal: the dat's flags, its polygon (a drawing polygon of the cell structure, in the cell's
/// frame, with its retail plane; null plane when degenerate), and the other side: a cell of the same
/// landblock, or outdoors (<see cref="OtherCellId"/> then ends in 0xFFFF).
/// </summary>
public sealed record CellPortalRecord(int Index, ushort Flags, ushort PolygonId, uint OtherCellId, ushort OtherPortalId,
    IReadOnlyList<Vector3> Vertices, Plane? Plane)
{
    /// <summary>The low 16 bits of <see cref="OtherCellId"/> for a portal that leads outdoors.</summary>
    public const ushort Outside = 0xFFFF;

    public bool LeadsOutside => (OtherCellId & 0xFFFF) == Outside;
}
