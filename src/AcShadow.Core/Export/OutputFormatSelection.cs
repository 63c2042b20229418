using System.Text;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Export;

/// <summary>
/// Turns a run's canonical files into the files the chosen formats ask for: the canonical ones as they are,
/// and for each BSP dump its acdream GfxObj file, for each cell file its acdream cell file. The acdream file is made from the canonical file's own
/// bytes (read back losslessly), so both formats always say the same thing.
/// </summary>
public static class OutputFormatSelection
{
    /// <summary>All of a run's files at once, sorted by path.</summary>
    public static IReadOnlyList<OutputFile> Apply(IEnumerable<OutputFile> canonical, OutputFormats formats) =>
        [.. canonical.SelectMany(f => For(f, formats)).OrderBy(f => f.RelativePath, StringComparer.Ordinal)];

    /// <summary>What one canonical file becomes (a batch streams its files one at a time).</summary>
    public static IReadOnlyList<OutputFile> For(OutputFile canonical, OutputFormats formats)
    {
        if (formats == OutputFormats.Canonical) return [canonical];
        var result = new List<OutputFile>(2);
        if (formats.HasFlag(OutputFormats.Canonical)) result.Add(canonical);
        if (formats.HasFlag(OutputFormats.Acdream) && canonical.Kind == FixtureKind.Bsp)
        {
            var dump = BspFileReader.Read(Encoding.UTF8.GetString(canonical.Content.Span));
            result.Add(new OutputFile(AcdreamGfxObjFormat.PathFor(canonical.Id), FixtureKind.AcdreamGfxObj, canonical.Id,
                AcdreamGfxObjWriter.Write(dump), 0, AcdreamGfxObjWriter.PolygonCount(dump)));
        }
        if (formats.HasFlag(OutputFormats.Acdream) && canonical.Kind == FixtureKind.Cell)
        {
            var cell = Fixtures.Cells.CellFileReader.Read(Encoding.UTF8.GetString(canonical.Content.Span));
            result.Add(new OutputFile(Fixtures.Cells.CellFileFormat.AcdreamPathFor(canonical.Id), FixtureKind.AcdreamCell, canonical.Id,
                AcdreamCellWriter.Write(cell), 0, AcdreamCellWriter.PolygonCount(cell)));
        }
        return result;
    }
}
