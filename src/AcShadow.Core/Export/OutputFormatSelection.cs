using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Export;

/// <summary>
/// Turns a run's canonical files into the files the chosen formats ask for: the canonical ones as they are,
/// and for each BSP dump and cell file its acdream file, written from the same in-memory records as the
/// canonical file, so both formats always say the same thing.
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
        if (formats.HasFlag(OutputFormats.Acdream) && canonical.Acdream is { } acdream) result.Add(acdream());
        return result;
    }
}
