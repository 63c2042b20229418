using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;

namespace AcShadow.Core.Batch;

/// <summary>
/// Runs a <see cref="BatchPlan"/> through the one <see cref="ExportEngine"/>: Setups in parallel (each
/// result lands in its plan slot, so the order never depends on scheduling), then the scene, then
/// index.json. Pure: returns bytes; the caller writes them.
/// </summary>
public static class BatchRunner
{
    public static BatchResult Run(ExportEngine engine, BatchPlan plan, BatchInputs inputs, int jobs,
        Action<BatchProgress>? progress = null, CancellationToken cancellation = default)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(jobs, 1);
        var total = plan.Setups.Count + (plan.Scene is null ? 0 : 1);
        var done = 0;
        var results = new (SetupExport? Export, string? Problem)[plan.Setups.Count];
        Parallel.For(0, plan.Setups.Count, new ParallelOptions { MaxDegreeOfParallelism = jobs, CancellationToken = cancellation }, i =>
        {
            results[i] = ExportOne(engine, plan.Setups[i].Id);
            progress?.Invoke(new BatchProgress(Interlocked.Increment(ref done), total));
        });

        var files = new SortedDictionary<string, OutputFile>(StringComparer.Ordinal);
        var skipped = new List<SkippedItem>(plan.Skipped);
        var diagnostics = new List<(uint, Diagnostic)>();
        var exports = new Dictionary<uint, SetupExport>();
        var problems = new Dictionary<uint, string>();
        for (var i = 0; i < results.Length; i++)
        {
            var planned = plan.Setups[i];
            var (export, problem) = results[i];
            if (export is null)
            {
                var reason = problem ?? SkippedItem.NotInDat;
                problems[planned.Id] = reason;
                skipped.Add(new SkippedItem(planned.Id, reason, planned.From));
                continue;
            }
            exports[planned.Id] = export;
            foreach (var file in export.Files) files.TryAdd(file.RelativePath, file);
            diagnostics.AddRange(export.Diagnostics.Select(d => (planned.Id, d)));
        }
        foreach (var id in plan.Skipped.Select(s => s.Id)) problems.TryAdd(id, SkippedItem.NotInDat);

        if (plan.Scene is { } scene)
        {
            var sceneExport = SceneExporter.Export(scene, engine, exports, problems);
            files[sceneExport.SceneFile.RelativePath] = sceneExport.SceneFile;
            foreach (var file in sceneExport.BspFiles) files.TryAdd(file.RelativePath, file);
            skipped.AddRange(sceneExport.Skipped);
            progress?.Invoke(new BatchProgress(Interlocked.Increment(ref done), total));
        }

        var ordered = OutputFormatSelection.Apply(files.Values, inputs.Formats);
        var sortedSkipped = skipped.OrderBy(s => s.Id).ToArray();
        var index = BatchIndexWriter.Write(inputs, ordered, sortedSkipped);
        return new BatchResult(ordered, index, sortedSkipped, exports.Count,
            ordered.Where(f => f.Kind is OutputKind.Bsp or OutputKind.AcdreamGfxObj).Select(f => f.Id).Distinct().Count(),
            ordered.Count(f => f.Kind == OutputKind.Scene), diagnostics);
    }

    /// <summary>A Setup that cannot be decoded is skipped with the reason; other Setups go on.</summary>
    private static (SetupExport?, string?) ExportOne(ExportEngine engine, uint id)
    {
        try
        {
            return (engine.ExportSetup(id), null);
        }
        catch (DatFormatException e)
        {
            return (null, $"unreadable: {e.Message}");
        }
    }
}
