using AcShadow.Core.Cells;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// The cell structures a landblock's cells use, read from the portal dat once per (Environment, index)
/// however many cells share one, as batch's cell export reads them (<see cref="CellGeometry"/>).
/// </summary>
public sealed class CellStructures(IDatSource portal)
{
    private readonly Dictionary<(uint, uint), (CellGeometry?, string?)> _known = [];

    /// <summary>The geometry, or why there is none (not in the dat, no such structure, unreadable).</summary>
    public (CellGeometry? Geometry, string? Problem) For(uint environmentId, uint index)
    {
        if (_known.TryGetValue((environmentId, index), out var known)) return known;
        (CellGeometry?, string?) result;
        try
        {
            var environment = portal.ReadEnvironment(environmentId);
            result = environment is null ? (null, $"Environment {JsonIds.Format(environmentId)}: not in the dat")
                : environment.Cell(index) is not { } shape ? (null, $"Environment {JsonIds.Format(environmentId)} has no cell structure {index}")
                : (CellGeometry.Of(environment, index, shape), null);
        }
        catch (DatFormatException e)
        {
            result = (null, $"Environment {JsonIds.Format(environmentId)}: unreadable: {e.Message}");
        }
        _known[(environmentId, index)] = result;
        return result;
    }
}
