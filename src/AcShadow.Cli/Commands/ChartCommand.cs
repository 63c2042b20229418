using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Chart.Output;
using AcShadow.Core.Chart;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow chart [--setup ID ...] [--doors] [--all] [--setups FILE] [--landblock 0xXXYY] --out DIR [--probe-radius R] [--spacing S]`:
/// every shape model against the retail reference on probes around each Setup (and each bare GfxObj a
/// landblock places); writes chart.csv,
/// summary.csv, failures.csv, speed-accuracy.svg and a failure map per Setup (docs/chart.md).
/// </summary>
public static class ChartCommand
{
    public static Command Create(CliConsole console)
    {
        var setup = new Option<string[]>("--setup") { Description = "a Setup id to chart, e.g. 0x020019FF (repeat for more)", HelpName = "ID" };
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var outDir = new Option<string>("--out") { Description = "output folder", HelpName = "DIR", Required = true };
        var radius = new Option<string?>("--probe-radius") { Description = $"query sphere radius in metres (default {F(ChartOptions.DefaultProbeRadius)}, a player)", HelpName = "R" };
        var spacing = new Option<string?>("--spacing") { Description = $"grid spacing in metres (default {F(ChartOptions.DefaultSpacing)})", HelpName = "S" };
        var scale = CommonOptions.Scale();
        var quiet = new Option<bool>("--quiet") { Description = "no progress display (the summary is still printed)" };
        var pose = new PoseOptions();
        var command = new Command("chart", "Chart every collision shape model against the retail reference: agreement, false passes, time per query")
        {
            setup, dat, selection.Doors, selection.All, selection.Setups, selection.Landblock, selection.CellDat, outDir, radius, spacing, scale, quiet,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse =>
        {
            var ids = (parse.GetValue(setup) ?? []).Select(t => ArgumentParsing.SetupId(t)).ToArray();
            var chosen = new BatchSelection(parse.GetValue(selection.Doors), parse.GetValue(selection.All), null, null);
            if (parse.GetValue(selection.Setups) is not null || parse.GetValue(selection.Landblock) is not null)
                chosen = selection.Parse(parse, defaultToAll: false);
            if (ids.Length == 0 && chosen.IsEmpty)
                throw new CliException(ExitCodes.Usage, "choose what to chart: --setup ID (repeatable), --doors, --all, --setups FILE and/or --landblock 0xXXYY");
            var options = new ChartOptions
            {
                ProbeRadius = Metres(parse.GetValue(radius), "--probe-radius", ChartOptions.DefaultProbeRadius),
                Spacing = Metres(parse.GetValue(spacing), "--spacing", ChartOptions.DefaultSpacing),
            };
            if (options.Problem() is { } problem) throw new CliException(ExitCodes.Usage, problem);
            return Run(console, ids, chosen, parse.GetValue(dat), parse.GetValue(selection.CellDat), parse.GetValue(outDir)!, options,
                ArgumentParsing.Scale(parse.GetValue(scale)), parse.GetValue(quiet),
                pose.Apply(parse, new Core.Shapes.ShapeBuildOptions(Fixtures.Shapes.ShapePolicy.Retail)));
        });
        return command;
    }

    private static int Run(CliConsole console, uint[] ids, BatchSelection selection, string? datPath, string? cellDatPath, string outDir, ChartOptions options, float scale, bool quiet, Core.Shapes.ShapeBuildOptions pose)
    {
        var clock = Stopwatch.StartNew();
        if (File.Exists(outDir))
            throw new CliException(ExitCodes.OutputFailed, $"--out: {outDir} is a file: pass a folder (it is created when missing)");
        using var dat = DatLocator.Open(datPath, cellDatPath, console);
        var missing = ids.Where(id => dat.Portal.ReadSetup(id) is null).ToArray();
        if (missing.Length > 0)
            throw new CliException(ExitCodes.NotInDat, $"Setup {string.Join(", ", missing.Select(JsonIds.Format))} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");
        // Times from unoptimised code are several times slower and would mislead the speed axis.
        if (typeof(ChartRunner).Assembly.GetCustomAttributes(typeof(DebuggableAttribute), false)
                .OfType<DebuggableAttribute>().Any(a => a.IsJITOptimizerDisabled))
            console.Error.WriteLine("acshadow: warning: this is a Debug build, so times per query are several times slower than a Release build's (dotnet run -c Release ...)");
        var planned = selection.IsEmpty ? null : SelectionOptions.Plan(selection, dat);
        OutputFolder.Prepare(outDir);
        var order = ids.Concat(planned?.Setups.Select(s => s.Id) ?? []).Distinct().ToArray();
        var bareGfxObjs = planned?.Scene?.GfxObjIds ?? [];

        var subjects = new ChartSubjects(dat.Portal, pose);
        // Like batch, a selected object that cannot be decoded is skipped with its reason; an id asked
        // for by --setup has been read above, so it is decodable.
        var unreadable = new List<uint>();
        ChartSubject? Decodable(uint id, Func<ChartSubject?> subject)
        {
            try
            {
                return subject();
            }
            catch (DatFormatException e)
            {
                console.Error.WriteLine($"warning: {JsonIds.Format(id)}: unreadable, skipped: {e.Message}");
                unreadable.Add(id);
                return null;
            }
        }
        var chosen = order.Select(id => Decodable(id, () => subjects.For(id, scale)))
            .Concat(bareGfxObjs.Select(id => Decodable(id, () => subjects.ForBareGfxObj(id, scale))))
            .OfType<ChartSubject>()
            .ToArray();
        var progress = new ProgressReporter(console.Error, console.IsTerminal, quiet || chosen.Length < 2, "objects charted");
        ChartReport report;
        try
        {
            report = ChartRunner.Run(chosen, options, progress: (done, total) => progress.Report(new BatchProgress(done, total)));
        }
        finally
        {
            progress.Finish();
        }
        foreach (var o in report.Objects)
            DiagnosticPrinter.Print(console.Error, JsonIds.Format(o.SetupId), o.Models[0].Diagnostics);

        long bytes = 0;
        var files = ChartFiles.Render(report);
        OutputFolder.RefuseForeignFiles(outDir, files.Select(f => (f.RelativePath, (ReadOnlyMemory<byte>)f.Content)));
        foreach (var file in files) bytes += OutputFolder.WriteAtomically(outDir, file.RelativePath, file.Content);

        var chartedSetups = order.Length - unreadable.Count(order.Contains);
        var w = console.Out;
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"chart: {report.Objects.Count} object(s) ({chartedSetups} Setup(s), {report.Objects.Count - chartedSetups} bare GfxObj(s)) from {dat.Description}, {report.Objects.Sum(o => o.Probes.Count)} probes (radius {options.ProbeRadius} m, spacing {options.Spacing} m), reference {report.Reference}"));
        foreach (var s in ModelSummary.All(report))
            w.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"  {s.Model,-18} {s.AgreementPercent,8:0.000}% agree  {s.FalsePass,7} false pass  {s.FalseBlock,7} false block  {s.Timing.MedianNs,8:0.0} ns/query median"));
        foreach (var o in report.Objects.Take(20))
            w.WriteLine($"  {JsonIds.Format(o.SetupId)}: cheapest exact model {(o.CheapestExact.Length == 0 ? "none" : o.CheapestExact)}");
        if (report.Objects.Count > 20) w.WriteLine($"  ... cheapest exact model of every setup in {Path.Combine(outDir, "chart.csv")}");
        foreach (var group in planned?.Skipped.GroupBy(s => s.Reason) ?? [])
            w.WriteLine($"  skipped {group.Count()} ({group.Key}): {string.Join(' ', group.Select(s => JsonIds.Format(s.Id)))}");
        if (unreadable.Count > 0)
            w.WriteLine($"  skipped {unreadable.Count} (unreadable, see the warnings): {string.Join(' ', unreadable.Select(JsonIds.Format))}");
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wrote {files.Count} file(s) ({bytes} bytes) to {outDir} in {clock.Elapsed.TotalSeconds:0.000} s; times are measurements and vary run to run"));
        return ExitCodes.Ok;
    }

    private static float Metres(string? text, string option, float fallback)
    {
        if (text is null) return fallback;
        if (float.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var v) && float.IsFinite(v) && v > 0f) return v;
        throw new CliException(ExitCodes.Usage, $"{option}: '{text}' is not a positive number of metres: use e.g. {F(fallback)}");
    }

    private static string F(float v) => v.ToString(CultureInfo.InvariantCulture);
}
