using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Analysis.Compile;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Bsp;
using AcShadow.Core.Catalog;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Files;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow scene --landblock 0xXXYY --out DIR [--mover-radius R ...] [--tolerance P]`: compiles a
/// landblock: every placed object gets the cheapest model that gives retail's answer on the chart's probes
/// (grid, doorway lines, stability probes for every mover radius); writes compiled-scene.json, the BSP
/// dumps only the objects left as retail need, scene-chart.csv and scene-chart.svg (docs/chart.md).
/// A verb of its own rather than a batch flag: batch exports every object in full, in parallel, with an
/// index; this probes and times one landblock's objects one after another, like chart, and writes less.
/// </summary>
public static class SceneCommand
{
    public static Command Create(CliConsole console)
    {
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.RequiredOut();
        var radius = CommonOptions.Metres(0.48f).Repeated("--mover-radius", "R",
            $"a mover sphere radius in metres to be exact for (repeat for more; default {ChartOptions.DefaultProbeRadius.ToString(CultureInfo.InvariantCulture)}, a player); the first also sizes the grid");
        var tolerance = new NumberRule<double>("a percentage from 0 to 100", "use e.g. 0.5") { From = 0, To = 100 }
            .Option("--tolerance", "P", "allow a model whose false blocks are at most P % of an object's probes (never a false pass; default 0: exact)");
        var spacing = CommonOptions.Metres(0.25f).Option("--spacing", "S", $"grid spacing in metres (default {ChartOptions.DefaultSpacing.ToString(CultureInfo.InvariantCulture)})");
        var scale = CommonOptions.Scale();
        var quiet = new Option<bool>("--quiet") { Description = "no progress display (the summary is still printed)" };
        var noCells = SelectionOptions.NoCells();
        var mover = ValueOptions.Single("--mover", "ID",
            "the Setup of the character whose walks a cheaper model must not let past retail's stops (default: the sample's person on the sample, else the standard human: docs/chart.md)",
            text => ArgumentParsing.SetupId(text, "--mover"));
        var command = new Command("scene", "Compile a landblock: each object's cheapest model that gives retail's answer, with the evidence and the scene's chart")
        {
            selection.Landblock, dat, selection.CellDat, outDir, radius, tolerance, spacing, scale, quiet, noCells, mover,
        };
        command.SetAction(parse =>
        {
            if (parse.GetValue(selection.Landblock) is null)
                throw new CliException(ExitCodes.Usage, "choose the landblock to compile: --landblock 0xXXYY");
            var chosen = SelectionOptions.WithoutCells(selection.Parse(parse, defaultToAll: false), parse.GetValue(noCells));
            var radii = parse.GetValue(radius) ?? [];
            var chart = new ChartOptions
            {
                ProbeRadius = radii.Length > 0 ? radii[0] : ChartOptions.DefaultProbeRadius,
                MoverRadii = radii.Skip(1).ToArray(),
                Spacing = parse.GetValue(spacing) ?? ChartOptions.DefaultSpacing,
            };
            var options = new SceneCompileOptions
            {
                Chart = chart,
                EntityScale = parse.GetValue(scale) ?? 1f,
                TolerancePercent = parse.GetValue(tolerance) ?? 0,
            };
            if (options.Problem() is { } problem) throw ChartOptionProblem.Refusal(problem);
            return Run(console, chosen, parse.GetValue(dat), parse.GetValue(selection.CellDat), parse.GetValue(outDir)!, options, parse.GetValue(quiet), parse.GetValue(mover));
        });
        return command;
    }

    /// <summary>The BSP dumps a compiled-scene.json names, read by the package's one reader; none when it is not a regular file or does not read as one.</summary>
    private static IReadOnlyList<string> DumpsNamedBy(string scenePath)
    {
        if (FileKinds.Of(scenePath) != FileKind.Regular) return [];
        try
        {
            var scene = CompiledSceneFile.Read(File.ReadAllText(scenePath));
            return [.. scene.DumpFiles().Where(f => RelativeOutputPath.StaysInside(f) && f.EndsWith(".bsp.json", StringComparison.Ordinal)).Distinct()];
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException or InvalidOperationException or FormatException or KeyNotFoundException)
        {
            return [];
        }
    }

    /// <summary>
    /// Removes the dumps the previous compiled-scene.json named that this run does not write (an object now
    /// modelled by a cheaper model needs no dump); <paramref name="beforeFirst"/> runs before the first removal.
    /// </summary>
    private static void RemoveDumpsNoLongerNamed(OutputFolder folder, IReadOnlyList<string> previous, IReadOnlyList<OutputFile> files, Action beforeFirst)
    {
        var written = files.Select(f => f.RelativePath).ToHashSet(StringComparer.Ordinal);
        foreach (var relative in previous.Where(p => !written.Contains(p)))
            folder.RemoveEarlier(relative, "a dump the previous compile named and this one does not", beforeFirst);
    }

    private static int Run(CliConsole console, BatchSelection selection, string? datPath, string? cellDatPath, string outDir, SceneCompileOptions options, bool quiet,
        uint? moverId)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, cellDatPath, console);
        var (moverSetup, walker) = MoveCommand.MoverOrStandard(moverId, dat);
        options = options with { Movement = new MovementChartOptions(walker, id => DoorCatalog.Find(id) is not null) };
        var scene = SelectionOptions.Plan(selection, dat).Scene!;
        if (typeof(SceneCompiler).Assembly.GetCustomAttributes(typeof(DebuggableAttribute), false)
                .OfType<DebuggableAttribute>().Any(a => a.IsJITOptimizerDisabled))
            console.Error.WriteLine("acshadow: warning: this is a Debug build, so times per query are several times slower than a Release build's (dotnet run -c Release ...)");
        using var folder = OutputFolder.Open(outDir, dat);

        var subjects = new ChartSubjects(dat.Portal);
        var placed = PlacedObject.Of(scene);
        var distinct = placed.Select(p => (p.Object.Kind, p.Object.Id)).Distinct().Count();
        var progress = new ProgressReporter(console.Error, console.IsTerminal, quiet || distinct < 2, "objects and cells compiled", "scene");
        CompiledSceneReport report;
        try
        {
            report = SceneCompiler.Compile(scene, subjects, options, new StopwatchQueryTimer(), (done, total) => progress.Report(new BatchProgress(done, total)));
        }
        finally
        {
            progress.Finish();
        }
        var warnings = new WarningSummary(console.Error);
        foreach (var (key, c) in report.Compiled)
            warnings.Add(JsonIds.Format(key.Id), c.Diagnostics);
        foreach (var cell in report.Cells)
            warnings.Add(JsonIds.Format(cell.Cell.Id), cell.Diagnostics);

        var files = CompiledSceneFiles.Render(report, id => subjects.GfxObj(id) is { } g ? BspExtractor.Extract(g) : null);
        folder.RefuseForeign(files);
        var previousDumps = DumpsNamedBy(Path.Combine(outDir, FileFormats.CompiledScene.Path));
        long bytes = 0;
        var sceneRemoved = false;
        void RemovePreviousScene()
        {
            if (!sceneRemoved) folder.RemoveEarlier(FileFormats.CompiledScene.Path, "the previous compile's scene, which names the dumps this run replaces");
            sceneRemoved = true;
        }
        foreach (var file in files)
        {
            console.Interrupted.ThrowIfCancellationRequested();
            // Before the new scene: the dumps only the previous one named go, so the folder holds one compile.
            if (file.RelativePath == FileFormats.CompiledScene.Path)
                RemoveDumpsNoLongerNamed(folder, previousDumps, files, RemovePreviousScene);
            if (folder.IsUnchanged(file.RelativePath, file.Content.Span))
            {
                bytes += file.Content.Length;
                continue;
            }
            // The previous compiled-scene.json names the previous dumps: it goes before the first of them is
            // replaced, and the new one is written last (CompiledSceneFiles), so no scene ever sits beside
            // dumps of another compile (a run stopped part-way leaves none, which view --scene says).
            RemovePreviousScene();
            bytes += folder.Write(file.RelativePath, file.Content);
        }
        folder.RequireStillInPlace();

        var t = report.Totals;
        var w = console.Out;
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"scene {LandblockIds.Short(scene.LandBlockInfoId)} from {dat.Description}: {placed.Count} placed object(s), {distinct} distinct, {scene.Cells.Count} indoor cell(s) kept as retail, mover radius {string.Join(", ", options.Chart.Radii.Select(r => r.ToString(CultureInfo.InvariantCulture) + " m"))}, tolerance {options.TolerancePercent} %"));
        foreach (var group in placed.Select(p => p.Object).GroupBy(o => report.For(o)?.Model ?? ObjectCompilation.UnresolvedLabel).OrderBy(g => g.Key, StringComparer.Ordinal))
            w.WriteLine($"  {group.Key,-18} {group.Count(),4} object(s): {string.Join(' ', group.Select(o => JsonIds.Format(o.Id)).Distinct().Take(8))}{(group.Select(o => o.Id).Distinct().Count() > 8 ? " ..." : "")}");
        var probes = report.Probes();
        w.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  probes checked: {probes.Total} ({probes})"));
        var walked = report.Compiled.Values.SelectMany(c => c.Candidates).Where(k => k.Movement is not null).ToArray();
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  movement: mover {(moverSetup is { } m ? JsonIds.Format(m) : "the standard human (no --mover)")}; {walked.Length} candidate model(s) walked over {report.Compiled.Values.Sum(c => c.Candidates.LastOrDefault()?.Movement?.Cases ?? 0)} case(s), {walked.Count(k => k.Movement!.FalsePasses > 0)} refused for a movement false pass"));
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  whole scene over {t.Positions} mover positions: all-retail {t.Retail.MedianNs:0.0} ns, compiled {t.Compiled.MedianNs:0.0} ns per position (median; {t.RetailOps:0.0} and {t.CompiledOps:0.0} counted operations); compiled agrees on {t.Agree} ({t.AgreementPercent:0.000}%), {t.FalsePass} false pass, {t.FalseBlock} false block"));
        if (warnings.Summary() is { } warned) w.WriteLine($"  {warned}");
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wrote {files.Count} file(s) ({bytes} bytes, {CompiledSceneWriter.BspGfxObjs(report).Count} GfxObj and {report.Cells.Count(c => c.Bsp is not null)} cell BSP dump(s)) to {outDir} in {clock.Elapsed.TotalSeconds:0.000} s; times are measurements and vary run to run"));
        return ExitCodes.Ok;
    }
}
