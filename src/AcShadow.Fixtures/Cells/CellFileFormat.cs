using AcShadow.Fixtures.Json;

namespace AcShadow.Fixtures.Cells;

/// <summary>Names of the cell file and of acdream's cell file (docs/formats.md).</summary>
public static class CellFileFormat
{
    public const string Format = FileFormats.Cell;

    /// <summary>Relative path of an EnvCell's file inside an output folder.</summary>
    public static string PathFor(uint cellId) => $"cells/{JsonIds.Format(cellId)}.cell.json";

    /// <summary>acdream names its cell fixtures 0x%08X.json (CellDumpSerializer's readers look for exactly that).</summary>
    public static string AcdreamPathFor(uint cellId) => $"cells/{JsonIds.Format(cellId)}.json";

    /// <summary>The other cell of a portal that leads outdoors, in the file: its low 16 bits are 0xFFFF.</summary>
    public const ushort Outside = 0xFFFF;
}
