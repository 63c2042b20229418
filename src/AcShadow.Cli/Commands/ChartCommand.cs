using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Cells;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Catalog;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Json;
using AcShadow.Files;
using AcShadow.Fixtures.Json;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow chart [--setup ID ...] [--doors] [--all] [--setups FILE] [--landblock 0xXXYY] --out DIR [--probe-radius R] [--spacing S]
/// [--movement [--mover ID] [--walk CASE]]`: every shape model against the retail reference on probes around each Setup (and each
/// bare GfxObj a landblock places); writes chart.csv, summary.csv, failures.csv, speed-accuracy.svg and a failure map per Setup;
/// with --movement also the movement chart: movement-chart.csv, movement-summary.csv and a movement map per object (docs/chart.md).
/// </summary>
public static class ChartCommand
{
    /// <summary>Decoded objects the dat keeps beneath the subjects' own cache.</summary>
    private const int WorkingSet = 256;

    public static Command Create(CliConsole console)
    {
        var setup = CommonOptions.SetupIds("a Setup id to chart, e.g. 0x020019FF (repeat for more)");
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.RequiredOut();
        var radius = CommonOptions.Metres(ChartOptions.DefaultProbeRadius).Option("--probe-radius", "R", $"query sphere radius in metres (default {F(ChartOptions.DefaultProbeRadius)}, a player)");
        var spacing = CommonOptions.Metres(ChartOptions.DefaultSpacing).Option("--spacing", "S", $"grid spacing in metres (default {F(ChartOptions.DefaultSpacing)})");
        var scale = CommonOptions.Scale();
        var quiet = new Option<bool>("--quiet") { Description = "no progress display (the summary is still printed)" };
        var jobs = SelectionOptions.Jobs("objects charted side by side (default 1: times per query are then measured undisturbed)");
        var pose = new PoseOptions();
        var noCells = SelectionOptions.NoCells();
        var movement = new Option<bool>("--movement") { Description = "also chart every model by movement: walk the movement cases `move` writes through each model (movement-chart.csv, movement-summary.csv, a movement map per object; docs/chart.md)" };
        var mover = MoveCommand.MoverOption();
        var walk = new Option<string?>("--walk") { Description = "with --movement: draw this case's walk for every model (movement-walk-<id>-<model>.svg), e.g. closed/out-in/lat+0.450/hdg+00/walk", HelpName = "CASE" };
        var command = new Command("chart", "Chart every collision shape model against the retail reference: agreement, false passes, time per query")
        {
            setup, dat, selection.Doors, selection.All, selection.Setups, selection.Landblock, selection.CellDat, noCells, outDir, radius, spacing, scale, quiet, jobs,
            movement, mover, walk,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse =>
        {
            var ids = parse.GetValue(setup) ?? [];
            var chosen = new BatchSelection(parse.GetValue(selection.Doors), parse.GetValue(selection.All), null, null);
            if (parse.GetValue(selection.Setups) is not null || parse.GetValue(selection.Landblock) is not null)
                chosen = selection.Parse(parse, defaultToAll: false);
            chosen = SelectionOptions.WithoutCells(chosen, parse.GetValue(noCells));
            if (ids.Length == 0 && chosen.IsEmpty)
                throw new CliException(ExitCodes.Usage, "choose what to chart: --setup ID (repeatable), --doors, --all, --setups FILE and/or --landblock 0xXXYY");
            var options = new ChartOptions
            {
                ProbeRadius = parse.GetValue(radius) ?? ChartOptions.DefaultProbeRadius,
                Spacing = parse.GetValue(spacing) ?? ChartOptions.DefaultSpacing,
            };
            if (options.Problem() is { } problem) throw ChartOptionProblem.Refusal(problem);
            var jobCount = parse.GetValue(jobs) ?? 1;
            var byMovement = parse.GetValue(movement);
            if (!byMovement && (parse.GetValue(mover) is not null || parse.GetValue(walk) is not null))
                throw new CliException(ExitCodes.Usage, "--mover and --walk apply to --movement: add --movement");
            return Run(console, ids, chosen, parse.GetValue(dat), parse.GetValue(selection.CellDat), parse.GetValue(outDir)!, options,
                parse.GetValue(scale) ?? 1f, parse.GetValue(quiet), jobCount,
                pose.Apply(parse, new Core.Shapes.ShapeBuildOptions(Fixtures.Shapes.ShapePolicy.Retail)),
                byMovement ? new MovementRequest(parse.GetValue(mover), parse.GetValue(walk)) : null);
        });
        return command;
    }

    /// <summary>What --movement, --mover and --walk ask for.</summary>
    private sealed record MovementRequest(uint? Mover, string? Walk);

    private static int Run(CliConsole console, uint[] ids, BatchSelection selection, string? datPath, string? cellDatPath, string outDir,
        ChartOptions options, float scale, bool quiet, int jobs, Core.Shapes.ShapeBuildOptions pose, MovementRequest? movementRequest)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, cellDatPath, console);
        var missing = ids.Where(id => dat.Portal.ReadSetup(id) is null).ToArray();
        if (missing.Length > 0)
            throw new CliException(ExitCodes.NotInDat, $"Setup {string.Join(", ", missing.Select(JsonIds.Format))} is not in {dat.Description}: check the id (`acshadow audit --all` lists every Setup the dat has)");
        // Times from unoptimised code are several times slower and would mislead the speed axis.
        if (typeof(ChartRunner).Assembly.GetCustomAttributes(typeof(DebuggableAttribute), false)
                .OfType<DebuggableAttribute>().Any(a => a.IsJITOptimizerDisabled))
            console.Error.WriteLine("acshadow: warning: this is a Debug build, so times per query are several times slower than a Release build's (dotnet run -c Release ...)");
        var planned = selection.IsEmpty ? null : SelectionOptions.Plan(selection, dat);
        var order = ids.Concat(planned?.Setups.Select(s => s.Id) ?? []).Distinct().ToArray();
        var bareGfxObjs = planned?.Scene?.GfxObjIds ?? [];
        var objectIds = order.Concat(bareGfxObjs).ToArray();
        PoseOptions.RequireUsable(pose, dat.Portal, order);

        using var folder = OutputFolder.Open(outDir, dat);
        var cells = planned?.Scene?.Cells ?? [];
        folder.RefuseForeign(ChartFiles.Heads(objectIds, cells.Count > 0 ? CellsCsv.Head : null));
        MovementChartOptions? movement = null;
        if (movementRequest is not null)
        {
            folder.RefuseForeign(MovementFiles.Heads(objectIds));
            var (moverId, walker) = MoveCommand.MoverOrStandard(movementRequest.Mover, dat);
            movement = new MovementChartOptions(walker, id => DoorCatalog.Find(id) is not null) { Walk = movementRequest.Walk };
            console.Out.WriteLine($"chart: walking the movement cases with mover {(moverId is { } m ? JsonIds.Format(m) : "the standard human (no --mover)")}");
        }

        // The subjects keep their own GfxObj cache; beneath it the dat keeps a bounded working set, so a chart
        // of the whole dat does not hold every object it decoded.
        var subjects = new ChartSubjects(dat.PortalWorkingSet(WorkingSet), pose);
        // Like batch, a selected object that cannot be decoded is skipped with its reason; an id asked
        // for by --setup has been read above, so it is decodable. The first few are warned about as they
        // come; the summary counts them all.
        var unreadable = new List<uint>();
        ChartSubject? SubjectAt(int i)
        {
            var id = objectIds[i];
            try
            {
                return i < order.Length ? subjects.For(id, scale) : subjects.ForBareGfxObj(id, scale);
            }
            catch (DatFormatException e)
            {
                lock (unreadable)
                {
                    unreadable.Add(id);
                    if (unreadable.Count <= IdSummary.Shown) console.Error.WriteLine($"warning: {JsonIds.Format(id)}: unreadable, skipped: {e.Message}");
                    else if (unreadable.Count == IdSummary.Shown + 1) console.Error.WriteLine("warning: more objects are unreadable; the summary counts them");
                }
                return null;
            }
        }

        var models = ShapeModels.All.Select(m => m.Name).ToArray();
        // Objects are not in size order (on the scale dat the BSP-bearing half comes first by id): the ETA weighs each by its parts' stored bytes.
        var silent = quiet || objectIds.Length < 2;
        var eta = new WorkWeightedEta(silent ? [] : ChartWork.Of(dat.Portal, order, bareGfxObjs));
        var progress = new ProgressReporter(console.Error, console.IsTerminal, silent, "objects charted", "chart", eta.Remaining);
        var charting = Stopwatch.StartNew();
        int charted = 0, mapsWritten = 0, movementCases = 0, movementMaps = 0, walksDrawn = 0;
        long bytes = 0, probes = 0;
        var cheapest = new List<string>();
        var warnings = new WarningSummary(console.Error);
        ChartTally tally = null!;
        try
        {
            // chart.csv and failures.csv grow object by object in their temporary files and are renamed into
            // place at the end; each failure map is written whole as soon as its object is done, so memory
            // stays flat however many objects there are.
            long failuresBytes = 0, movementBytes = 0;
            var chartBytes = folder.Write("chart.csv", chartCsv =>
                failuresBytes = folder.Write("failures.csv", failuresCsv =>
                movementBytes = WriteMovementCsv(folder, movement is not null, movementCsv =>
                {
                    var chartRows = new StreamWriter(chartCsv, new UTF8Encoding(false), 1 << 16);
                    var failureRows = new StreamWriter(failuresCsv, new UTF8Encoding(false), 1 << 16);
                    var movementRows = movementCsv is null ? null : new StreamWriter(movementCsv, new UTF8Encoding(false), 1 << 16);
                    var files = ChartFiles.Begin(chartRows, failureRows, options, models);
                    var movementFiles = movementRows is null ? null : MovementFiles.Begin(movementRows);
                    tally = ChartRunner.Stream(objectIds.Length, SubjectAt, options, chart =>
                    {
                        warnings.Add(JsonIds.Format(chart.SetupId), chart.Models[0].Diagnostics, chart.Notes);
                        var map = files.Add(chart);
                        // The previous run's tables describe other maps: they go before the first map is
                        // replaced, so a run stopped part-way leaves no chart.csv its maps contradict.
                        if (mapsWritten == 0)
                        {
                            RemovePreviousTables(outDir);
                            RemoveMapsNotCharted(folder, objectIds);
                        }
                        bytes += folder.Write(map.RelativePath, map.Content);
                        mapsWritten++;
                        if (chart.Movement is { } moved && movementFiles is not null)
                        {
                            if (moved.Walk is not null) walksDrawn++;
                            foreach (var file in movementFiles.Add(moved))
                            {
                                bytes += folder.Write(file.RelativePath, file.Content);
                                movementMaps++;
                            }
                            movementCases += moved.Cases.Count;
                        }
                        charted++;
                        probes += chart.Probes.Count;
                        if (cheapest.Count < 20) cheapest.Add($"  {JsonIds.Format(chart.SetupId)}: cheapest exact model {(chart.CheapestExact.Length == 0 ? "none" : chart.CheapestExact)}");
                    }, progress: (done, total) =>
                    {
                        eta.Record(done, charting.Elapsed);
                        progress.Report(new BatchProgress(done, total));
                        dat.RequireUnchanged();
                    }, jobs: jobs, cancellation: console.Interrupted, movement: movement);
                    chartRows.Flush();
                    failureRows.Flush();
                    movementRows?.Flush();
                })));
            bytes += chartBytes + failuresBytes + movementBytes;
            dat.RequireUnchanged();
        }
        catch (AggregateException e) when (e.InnerExceptions.OfType<CliException>().FirstOrDefault() is { } first)
        {
            throw first;
        }
        catch (OperationCanceledException) when (console.Interrupted.IsCancellationRequested)
        {
            throw new CliException(ExitCodes.Interrupted, string.Create(CultureInfo.InvariantCulture,
                $"{Interrupt.Word}: {mapsWritten} failure map(s) of {objectIds.Length} object(s) were written to {outDir}, each whole; chart.csv, summary.csv, failures.csv and speed-accuracy.svg were not (nor are an earlier run's left), so the folder is incomplete: run the same chart again"));
        }
        finally
        {
            progress.Finish();
        }
        // The landblock's indoor cells, probed as `acshadow scene` probes them and answered by their retail trees.
        var cellCharts = new List<CellChart>(cells.Count);
        if (cells.Count > 0)
        {
            var structures = new CellStructures(dat.Portal);
            var cellTimer = new StopwatchQueryTimer();
            foreach (var cell in cells)
            {
                console.Interrupted.ThrowIfCancellationRequested();
                var cellChart = CellChart.Of(cell, structures, options, cellTimer);
                warnings.Add(JsonIds.Format(cell.Id), cellChart.Cell.Diagnostics);
                cellCharts.Add(cellChart);
            }
            bytes += folder.Write(CellsCsv.FileName, new UTF8Encoding(false).GetBytes(CellsCsv.Write(cellCharts)));
            dat.RequireUnchanged();
        }
        var summaries = tally.Summaries();
        var movementSummaries = movement is null ? null : tally.Movement.Summaries();
        foreach (var total in ChartFiles.Totals(options, models, tally.Objects, summaries, movementSummaries))
            bytes += folder.Write(total.RelativePath, total.Content);
        folder.RequireStillInPlace();

        var chartedSetups = order.Length - unreadable.Count(order.Contains);
        var w = console.Out;
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"chart: {charted} object(s) ({chartedSetups} Setup(s), {charted - chartedSetups} bare GfxObj(s)) from {dat.Description}, {probes} probes (radius {options.ProbeRadius} m, spacing {options.Spacing} m), reference {models[0]}"));
        foreach (var s in summaries)
            w.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"  {s.Model,-18} {s.AgreementPercent,8:0.000}% agree  {s.FalsePass,7} false pass  {s.FalseBlock,7} false block  {s.Timing.MedianNs,8:0.0} ns/query median"));
        if (movementRequest?.Walk is { } walkId && walksDrawn == 0)
            console.Error.WriteLine($"warning: --walk {walkId}: no charted object has that case, so no walk was drawn (a case id reads like closed/out-in/lat+0.450/hdg+00/walk; movement-chart.csv's first_diverging_case column shows some)");
        if (movementSummaries is not null)
        {
            w.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  movement: {movementCases} walk(s) per model; verdicts over non-fragile walks (fragile counted apart), time per transition"));
            foreach (var s in movementSummaries)
                w.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"  {s.Model,-18} {s.AgreementPercent,8:0.000}% agree  {string.Join("  ", MovementVerdicts.All.Skip(1).Select(v => $"{s.Counts[(int)v]} {MovementVerdicts.Name(v).Replace('_', ' ')}"))}  {s.FragileCases} fragile ({s.FragileFalsePass} false pass)  {s.NsPerTransition / 1000,8:0.0} µs/transition"));
        }
        foreach (var line in cheapest) w.WriteLine(line);
        if (cellCharts.Count > 0)
            w.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"  {cellCharts.Count} indoor cell(s) probed as retail ({cellCharts.Sum(c => c.Answers.Length)} probes, {cellCharts.Sum(c => c.Blocked)} blocked by their walls, floors and ceilings): {Path.Combine(outDir, CellsCsv.FileName)}"));
        if (charted > 20) w.WriteLine($"  ... cheapest exact model of every setup in {Path.Combine(outDir, "chart.csv")}");
        foreach (var group in planned?.Skipped.GroupBy(s => s.Reason) ?? [])
            w.WriteLine($"  skipped {group.Count()} ({group.Key}): {IdSummary.Of(group.Select(s => s.Id).ToArray())}");
        if (unreadable.Count > 0)
            w.WriteLine($"  skipped {unreadable.Count} (unreadable, see the warnings): {IdSummary.Of(unreadable.Order().ToArray())}");
        if (warnings.Summary() is { } warned) w.WriteLine($"  {warned}");
        w.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wrote {4 + mapsWritten + (cellCharts.Count > 0 ? 1 : 0) + (movement is null ? 0 : 2 + movementMaps)} file(s) ({bytes} bytes) to {outDir} in {clock.Elapsed.TotalSeconds:0.000} s{(jobs > 1 ? $" with {jobs} jobs" : "")}; times are measurements and vary run to run"));
        return ExitCodes.Ok;
    }

    /// <summary>movement-chart.csv through <paramref name="write"/> when the chart walks (its bytes), else <paramref name="write"/> with no stream (0).</summary>
    private static long WriteMovementCsv(OutputFolder folder, bool movement, Action<Stream?> write)
    {
        if (movement) return folder.Write(MovementFiles.ChartFile, write);
        write(null);
        return 0;
    }

    /// <summary>The tables and the speed chart a finished run wrote (checked as ours before the run began).</summary>
    private static void RemovePreviousTables(string outDir)
    {
        foreach (var name in (ReadOnlySpan<string>)["chart.csv", "summary.csv", "failures.csv", "speed-accuracy.svg", MovementFiles.ChartFile, MovementFiles.SummaryFile])
        {
            var path = OutputPaths.Target(outDir, name);
            try
            {
                if (FileKinds.Of(path) == FileKind.Regular) File.Delete(path);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new CliException(ExitCodes.OutputFailed, $"cannot remove the previous run's {path} before replacing its failure maps: {e.Message}");
            }
        }
    }

    /// <summary>
    /// An earlier run's failure maps of objects this run does not chart (an interrupted run's, or another
    /// selection's): left, they would sit beside this run's chart.csv, which does not describe them. Only
    /// maps that are acshadow's (their root element) are removed.
    /// </summary>
    private static void RemoveMapsNotCharted(OutputFolder folder, IEnumerable<uint> objectIds)
    {
        var charted = objectIds.Select(FailureMapSvg.FileName).ToHashSet(StringComparer.Ordinal);
        var head = ChartFiles.Heads([0]).Single(f => f.RelativePath == FailureMapSvg.FileName(0)).Content;
        foreach (var path in Directory.EnumerateFiles(folder.Root, FailureMapSvg.FilePattern).Order(StringComparer.Ordinal))
            if (!charted.Contains(Path.GetFileName(path)) && ForeignFileGuard.IsOurs(path, head.Span))
                folder.RemoveEarlier(Path.GetFileName(path), "an earlier run's map of an object this run does not chart");
    }

    private static string F(float v) => v.ToString(CultureInfo.InvariantCulture);
}
