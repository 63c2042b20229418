using System.Collections.Concurrent;
using AcShadow.Core.Catalog;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Movement;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Batch;

/// <summary>
/// Runs a <see cref="BatchPlan"/> through the one <see cref="ExportEngine"/>: Setups in parallel, each
/// file handed to the caller's writer as soon as it is made (each path once; a shared GfxObj's dump by
/// whichever Setup needs it first), in the formats the inputs ask for, then the landblock's cells, then the scene, then index.json
/// from the files' entries, sorted by path, so the output never depends on scheduling. Only entries are
/// kept, never file bytes: memory stays bounded whatever the dat's size. Pure: the caller writes.
/// </summary>
public static class BatchRunner
{
    /// <summary>Everything in memory (verify): the same run, its files collected and sorted by path.</summary>
    public static BatchResult Run(IDatSource dat, ShapeBuildOptions options, BatchPlan plan, BatchInputs inputs, int jobs,
        Action<BatchProgress>? progress = null, CancellationToken cancellation = default)
    {
        var files = new ConcurrentDictionary<string, OutputFile>(StringComparer.Ordinal);
        // A streamed file's bytes may be lent for the call only: the ones kept are copies.
        var summary = Stream(dat, options, plan, inputs, jobs, f => files.TryAdd(f.RelativePath, f with { Content = f.Content.ToArray(), Acdream = null }), null, progress, cancellation);
        var ordered = files.Values.OrderBy(f => f.RelativePath, StringComparer.Ordinal).ToArray();
        return new BatchResult(ordered, summary.IndexJson(), summary.Skipped, summary.SetupsWritten, summary.BspDumps, summary.Scenes, summary.Diagnostics);
    }

    /// <param name="write">
    /// Called from worker threads, once per file path, as each file is made. A file's bytes may be lent
    /// (<see cref="OutputFile"/>): write or copy them before returning.
    /// </param>
    /// <param name="reuse">With --incremental: the previous run's state; a Setup whose inputs are unchanged is not decoded.</param>
    public static BatchSummary Stream(IDatSource dat, ShapeBuildOptions options, BatchPlan plan, BatchInputs inputs, int jobs,
        Action<OutputFile> write, BatchReuse? reuse, Action<BatchProgress>? progress = null, CancellationToken cancellation = default)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(jobs, 1);
        IReadOnlyList<FileEntry> Emit(OutputFile canonical)
        {
            var entries = new List<FileEntry>(2);
            foreach (var file in OutputFormatSelection.For(canonical, inputs.Formats))
            {
                write(file);
                entries.Add(FileEntry.Of(file));
            }
            return entries;
        }
        var engine = new ExportEngine(dat, options, Emit);
        var total = plan.Setups.Count + (plan.Scene is null ? 0 : 1);
        var done = 0;
        var results = new SetupOutcome[plan.Setups.Count];
        Parallel.For(0, plan.Setups.Count, new ParallelOptions { MaxDegreeOfParallelism = jobs, CancellationToken = cancellation }, i =>
        {
            var id = plan.Setups[i].Id;
            results[i] = reuse?.TryReuse(id) ?? ExportOne(engine, id, Emit, reuse);
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
            setupFiles[planned.Id] = FileFormats.Shadow.PathFor(planned.Id);
            diagnostics += outcome.Record.Diagnostics;
            if (outcome.Record.Diagnostics > 0) withDiagnostics++;
            if (outcome.Reused) reused++;
            records.Add(outcome.Record);
        }
        foreach (var id in plan.Skipped.Select(s => s.Id)) problems.TryAdd(id, SkippedItem.NotInDat);

        if (plan.Scene is { } scene)
        {
            // The cells first: scene.json lists their files. Each cell structure becomes geometry once.
            var cellExporter = new CellExporter(engine);
            var cells = scene.Cells.Select(c => cellExporter.Export(c, scene, setupFiles, problems)).ToArray();
            foreach (var cell in cells)
            {
                if (cell.File is { } cellFile)
                    foreach (var entry in Emit(cellFile)) files[entry.RelativePath] = entry;
                foreach (var entry in cell.BspEntries) files.TryAdd(entry.RelativePath, entry);
                skipped.AddRange(cell.Skipped);
            }
            skipped.AddRange(scene.MissingCells.Select(m => new SkippedItem(m.Id, m.Reason, SelectionSource.Landblock)));
            var sceneExport = SceneExporter.Export(scene, engine, setupFiles, problems, cells);
            foreach (var entry in Emit(sceneExport.SceneFile)) files[entry.RelativePath] = entry;
            foreach (var entry in sceneExport.BspEntries) files.TryAdd(entry.RelativePath, entry);
            skipped.AddRange(sceneExport.Skipped);
            progress?.Invoke(new BatchProgress(Interlocked.Increment(ref done), total));
        }

        if (inputs.Movement is { } movement) AddMovement(dat, movement, jobs, write, files, skipped, cancellation);

        var ordered = files.Values.ToArray();
        var sortedSkipped = skipped.OrderBy(s => s.Id).ToArray();
        var state = new IncrementalState(IncrementalState.ToolKey(options, inputs.Formats), records);
        return new BatchSummary(ordered, inputs, sortedSkipped, records.Count,
            ordered.Where(f => f.Kind is FixtureKind.Bsp or FixtureKind.AcdreamGfxObj).Select(f => f.Id).Distinct().Count(),
            ordered.Count(f => f.Kind == FixtureKind.Scene), new DiagnosticCount(diagnostics, withDiagnostics), reused, state);
    }

    /// <summary>
    /// `--movement`: each object's movement suite, and the BSP dumps it names that the Setups did not already
    /// write. Always in the canonical format (the cases reference the canonical BSP dumps). An object or mover
    /// the dat lacks is skipped.
    /// </summary>
    private static void AddMovement(IDatSource dat, MovementSelection movement, int jobs, Action<OutputFile> write,
        SortedDictionary<string, FileEntry> files, List<SkippedItem> skipped, CancellationToken cancellation)
    {
        var mover = MoverSetup.Read(dat, movement.Mover);
        foreach (var id in movement.Setups)
        {
            if (mover is null || dat.ReadSetup(id) is null)
            {
                skipped.Add(new SkippedItem(mover is null ? movement.Mover : id, SkippedItem.NotInDat, SelectionSource.None));
                continue;
            }
            var generated = MovementSuiteBuilder.Build(dat, id, movement.Mover, mover, DoorCatalog.Find(id) is not null, null, jobs, cancellation);
            foreach (var file in MovementExport.Files(generated))
            {
                if (files.ContainsKey(file.RelativePath)) continue;
                write(file);
                files[file.RelativePath] = FileEntry.Of(file);
            }
        }
    }

    /// <summary>A Setup that cannot be decoded is skipped with the reason; other Setups go on.</summary>
    private static SetupOutcome ExportOne(ExportEngine engine, uint id, Func<OutputFile, IReadOnlyList<FileEntry>> emit, BatchReuse? reuse)
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
        FileEntry[] files = [.. emit(export.Shadow), .. export.BspEntries];
        // What the files depend on besides the Setup: its parts, and the motion tables and animations its pose read.
        var parts = export.Setup.Parts.Concat(export.MotionInputs).Distinct().Order().ToArray();
        var fingerprint = reuse?.Fingerprint(id, parts) ?? "";
        return new SetupOutcome(null, files, new IncrementalSetup(id, fingerprint, parts, export.Diagnostics.Count, files), false);
    }
}

/// <summary>One Setup's part of a run: its files' entries and its incremental record, or why it was skipped.</summary>
public sealed record SetupOutcome(string? Problem, IReadOnlyList<FileEntry> Files, IncrementalSetup Record, bool Reused)
{
    public static SetupOutcome Failed(string problem) => new(problem, [], new IncrementalSetup(0, "", [], 0, []), false);
}
