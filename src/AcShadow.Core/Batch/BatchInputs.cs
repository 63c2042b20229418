using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Everything a batch's output depends on, as index.json records it so verify can regenerate the same
/// files: the dat(s), the policy, the entity scale and the selection. <see cref="CellDat"/> is recorded
/// only when a landblock is selected (only then does the output depend on it).
/// </summary>
public sealed record BatchInputs(DatSourceInfo Dat, DatSourceInfo? CellDat, ShapePolicy Policy, float EntityScale, BatchSelection Selection)
{
    /// <summary>`--format`; index.json records it only when it is not the default, so older indexes read as canonical.</summary>
    public OutputFormats Formats { get; init; } = OutputFormats.Canonical;
}
