using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Core.Batch;

/// <summary>
/// A batch run's output in memory (what verify compares): every file (sorted by path, each once),
/// index.json, what was skipped, and counts. The same inputs give the same bytes whatever the parallelism.
/// </summary>
public sealed record BatchResult(
    IReadOnlyList<OutputFile> Files,
    byte[] IndexJson,
    IReadOnlyList<SkippedItem> Skipped,
    int SetupsWritten,
    int BspDumps,
    int Scenes,
    DiagnosticCount Diagnostics)
{
    /// <summary>Every file including index.json (last), as written to disk.</summary>
    public IEnumerable<OutputFile> AllFiles => Files.Append(new OutputFile(FileFormats.Index.Path, IndexJson));
}
