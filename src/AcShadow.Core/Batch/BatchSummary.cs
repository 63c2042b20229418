using AcShadow.Core.Export;

namespace AcShadow.Core.Batch;

/// <summary>
/// A streamed batch run's outcome: the entry of every file written (sorted by path, each once), the
/// bytes of index.json (written last), what was skipped, counts for the summary, how many Setups were
/// reused unchanged by --incremental, and the state the next --incremental run starts from.
/// </summary>
public sealed record BatchSummary(
    IReadOnlyList<FileEntry> Files,
    byte[] IndexJson,
    IReadOnlyList<SkippedItem> Skipped,
    int SetupsWritten,
    int BspDumps,
    int Scenes,
    DiagnosticCount Diagnostics,
    int SetupsReused,
    IncrementalState State);
