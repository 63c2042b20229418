using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Export;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Cells;

/// <summary>
/// The cell structures a landblock's cells use, read from the portal dat and turned into geometry once per
/// (Environment, index) however many cells share one: the one lookup behind the cell export and the scene
/// compile. Thread-safe.
/// </summary>
public sealed class CellStructures(IDatSource portal)
{
    private readonly Dictionary<(uint, uint), (CellGeometry?, string?)> _known = [];
    private readonly Lock _lock = new();

    /// <summary>The geometry, or why there is none (not in the dat, no such structure, unreadable).</summary>
    public (CellGeometry? Geometry, string? Problem) For(uint environmentId, uint index)
    {
        lock (_lock)
        {
            if (_known.TryGetValue((environmentId, index), out var known)) return known;
            (CellGeometry?, string?) result;
            try
            {
                var environment = portal.ReadEnvironment(environmentId);
                result = environment is null ? (null, $"Environment {JsonIds.Format(environmentId)}: {SkippedItem.NotInDat}")
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
}
