using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Bsp;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
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
        var command = new Command("scene", "Compile a landblock: each object's cheapest model that gives retail's answer, with the evidence and the scene's chart")
        {
            selection.Landblock, dat, selection.CellDat, outDir, radius, tolerance, spacing, scale, quiet, noCells,
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
            return Run(console, chosen, parse.GetValue(dat), parse.GetValue(selection.CellDat), parse.GetValue(outDir)!, options, parse.GetValue(quiet));
        });
        return command;
    }

    private static int Run(CliConsole console, BatchSelection selection, string? datPath, string? cellDatPath, string outDir, SceneCompileOptions options, bool quiet)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, cellDatPath, console);
        var scene = SelectionOptions.Plan(selection, dat).Scene!;
        if (typeof(SceneCompiler).Assembly.GetCustomAttributes(typeof(DebuggableAttribute), false)
                .OfType<DebuggableAttribute>().Any(a => a.IsJITOptimizerDisabled))
            console.Error.WriteLine("acshadow: warning: this is a Debug build, so times per query are several times slower than a Release build's (dotnet run -c Release ...)");
        using var folder = OutputFolder.Open(outDir);

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
        long bytes = 0;
        foreach (var file in files)
        {
            console.Interrupted.ThrowIfCancellationRequested();
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
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  whole scene over {t.Positions} mover positions: all-retail {t.Retail.MedianNs:0.0} ns, compiled {t.Compiled.MedianNs:0.0} ns per position (median; {t.RetailOps:0.0} and {t.CompiledOps:0.0} counted operations); compiled agrees on {t.Agree} ({t.AgreementPercent:0.000}%), {t.FalsePass} false pass, {t.FalseBlock} false block"));
        if (warnings.Summary() is { } warned) w.WriteLine($"  {warned}");
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wrote {files.Count} file(s) ({bytes} bytes, {CompiledSceneWriter.BspGfxObjs(report).Count} GfxObj and {report.Cells.Count(c => c.Bsp is not null)} cell BSP dump(s)) to {outDir} in {clock.Elapsed.TotalSeconds:0.000} s; times are measurements and vary run to run"));
        return ExitCodes.Ok;
    }
}
