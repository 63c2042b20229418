using System.Collections.Concurrent;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Runs a <see cref="BatchPlan"/> through the one <see cref="ExportEngine"/>: Setups in parallel, each
/// file handed to the caller's writer as soon as it is made (each path once; a shared GfxObj's dump by
/// whichever Setup needs it first), then the scene, then index.json from the files' entries, sorted by
/// path, so the output never depends on scheduling. Only entries are kept, never file bytes: memory
/// stays bounded whatever the dat's size. Pure: the caller writes.
/// </summary>
public static class BatchRunner
{
    /// <summary>Everything in memory (verify): the same run, its files collected and sorted by path.</summary>
    public static BatchResult Run(IDatSource dat, ShapeBuildOptions options, BatchPlan plan, BatchInputs inputs, int jobs,
        Action<BatchProgress>? progress = null, CancellationToken cancellation = default)
    {
        var files = new ConcurrentDictionary<string, OutputFile>(StringComparer.Ordinal);
        var summary = Stream(dat, options, plan, inputs, jobs, f => files.TryAdd(f.RelativePath, f), null, progress, cancellation);
        var ordered = files.Values.OrderBy(f => f.RelativePath, StringComparer.Ordinal).ToArray();
        return new BatchResult(ordered, summary.IndexJson, summary.Skipped, summary.SetupsWritten, summary.BspDumps, summary.Scenes, summary.Diagnostics);
    }

    /// <param name="write">Called from worker threads, once per file path, as each file is made.</param>
    /// <param name="reuse">With --incremental: the previous run's state; a Setup whose inputs are unchanged is not decoded.</param>
    public static BatchSummary Stream(IDatSource dat, ShapeBuildOptions options, BatchPlan plan, BatchInputs inputs, int jobs,
        Action<OutputFile> write, BatchReuse? reuse, Action<BatchProgress>? progress = null, CancellationToken cancellation = default)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(jobs, 1);
        var engine = new ExportEngine(dat, options, write);
        var total = plan.Setups.Count + (plan.Scene is null ? 0 : 1);
        var done = 0;
        var results = new SetupOutcome[plan.Setups.Count];
        Parallel.For(0, plan.Setups.Count, new ParallelOptions { MaxDegreeOfParallelism = jobs, CancellationToken = cancellation }, i =>
        {
            var id = plan.Setups[i].Id;
            results[i] = reuse?.TryReuse(id) ?? ExportOne(engine, id, write, reuse);
            progress?.Invoke(new BatchProgress(Interlocked.Increment(ref done), total));
        });

        var files = new SortedDictionary<string, FileEntry>(StringComparer.Ordinal);
        var skipped = new List<SkippedItem>(plan.Skipped);
        var setupFiles = new Dictionary<uint, string>();
        var problems = new Dictionary<uint, string>();
        var records = new List<IncrementalSetup>();
        int diagnostics = 0, withDiagnostics = 0, reused = 0;
        for (var i = 0; i < results.Length; i++)
        {
            var planned = plan.Setups[i];
            var outcome = results[i];
            if (outcome.Problem is { } problem)
            {
                problems[planned.Id] = problem;
                skipped.Add(new SkippedItem(planned.Id, problem, planned.From));
                continue;
            }
            foreach (var file in outcome.Files) files[file.RelativePath] = file;
            setupFiles[planned.Id] = outcome.Files[0].RelativePath;
            diagnostics += outcome.Record.Diagnostics;
            if (outcome.Record.Diagnostics > 0) withDiagnostics++;
            if (outcome.Reused) reused++;
            records.Add(outcome.Record);
        }
        foreach (var id in plan.Skipped.Select(s => s.Id)) problems.TryAdd(id, SkippedItem.NotInDat);

        var scenes = 0;
        if (plan.Scene is { } scene)
        {
            var sceneExport = SceneExporter.Export(scene, engine, setupFiles, problems);
            write(sceneExport.SceneFile);
            files[sceneExport.SceneFile.RelativePath] = FileEntry.Of(sceneExport.SceneFile);
            foreach (var entry in sceneExport.BspEntries) files.TryAdd(entry.RelativePath, entry);
            skipped.AddRange(sceneExport.Skipped);
            scenes = 1;
            progress?.Invoke(new BatchProgress(Interlocked.Increment(ref done), total));
        }

        var ordered = files.Values.ToArray();
        var sortedSkipped = skipped.OrderBy(s => s.Id).ToArray();
        var index = BatchIndexWriter.Write(inputs, ordered, sortedSkipped);
        var state = new IncrementalState(IncrementalState.ToolKey(options), records);
        return new BatchSummary(ordered, index, sortedSkipped, records.Count, ordered.Count(f => f.Kind == OutputKind.Bsp), scenes,
            new DiagnosticCount(diagnostics, withDiagnostics), reused, state);
    }

    /// <summary>A Setup that cannot be decoded is skipped with the reason; other Setups go on.</summary>
    private static SetupOutcome ExportOne(ExportEngine engine, uint id, Action<OutputFile> write, BatchReuse? reuse)
    {
        SetupExport? export;
        try
        {
            export = engine.ExportSetup(id);
        }
        catch (DatFormatException e)
        {
            return SetupOutcome.Failed($"unreadable: {e.Message}");
        }
        if (export is null) return SetupOutcome.Failed(SkippedItem.NotInDat);
        write(export.Shadow);
        FileEntry[] files = [FileEntry.Of(export.Shadow), .. export.BspEntries];
        var parts = export.Setup.Parts.Distinct().Order().ToArray();
        var fingerprint = reuse?.Fingerprint(id, parts) ?? "";
        return new SetupOutcome(null, files, new IncrementalSetup(id, fingerprint, parts, export.Diagnostics.Count, files), false);
    }
}

/// <summary>One Setup's part of a run: its files' entries and its incremental record, or why it was skipped.</summary>
public sealed record SetupOutcome(string? Problem, IReadOnlyList<FileEntry> Files, IncrementalSetup Record, bool Reused)
{
    public static SetupOutcome Failed(string problem) => new(problem, [], new IncrementalSetup(0, "", [], 0, []), false);
}
