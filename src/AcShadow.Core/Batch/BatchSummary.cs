using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Batch;

/// <summary>
/// A streamed batch run's outcome: the entry of every file written (sorted by path, each once), what
/// index.json (written last) is made from, what was skipped, counts for the summary, how many Setups
/// were reused unchanged by --incremental, and the state the next --incremental run starts from.
/// </summary>
public sealed record BatchSummary(
    IReadOnlyList<FileEntry> Files,
    BatchInputs Inputs,
    IReadOnlyList<SkippedItem> Skipped,
    int SetupsWritten,
    int BspDumps,
    int Scenes,
    DiagnosticCount Diagnostics,
    int SetupsReused,
    IncrementalState State)
{
    /// <summary>Cell files written (a landblock's indoor cells).</summary>
    public int Cells => Files.Count(f => f.Kind == FixtureKind.Cell);

    /// <summary>index.json, streamed: on a retail dat it is megabytes, written at the end of the run.</summary>
    public void WriteIndex(Stream destination) => BatchIndexWriter.Write(destination, Inputs, Files, Skipped);

    /// <summary>index.json's bytes, in memory.</summary>
    public byte[] IndexJson() => BatchIndexWriter.Write(Inputs, Files, Skipped);
}
