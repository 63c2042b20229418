using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Export;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow batch --out DIR [selection]`: many Setups (and a landblock's scene) through the one export
/// engine, in parallel, written atomically with index.json; skipped ids are reported, never fatal.
/// </summary>
public static class BatchCommand
{
    public static Command Create(CliConsole console)
    {
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var outDir = new Option<string>("--out") { Description = "output folder", HelpName = "DIR", Required = true };
        var policy = CommonOptions.Policy();
        var scale = CommonOptions.Scale();
        var jobs = SelectionOptions.Jobs();
        var quiet = new Option<bool>("--quiet") { Description = "no progress display (the summary is still printed)" };
        var incremental = new Option<bool>("--incremental") { Description = "leave files whose content would not change untouched" };
        var format = FormatOption.Create();
        var command = new Command("batch", "Export many Setups (door catalog, all, a list, a landblock's scene) with index.json")
        {
            outDir, dat, selection.CellDat, selection.Doors, selection.All, selection.Setups, selection.Landblock,
            policy, scale, jobs, quiet, incremental, format,
        };
        command.SetAction(parse => Run(console,
            selection.Parse(parse, defaultToAll: false),
            parse.GetValue(dat),
            parse.GetValue(selection.CellDat),
            parse.GetValue(outDir)!,
            new ShapeBuildOptions(ArgumentParsing.Policy(parse.GetValue(policy)), ArgumentParsing.Scale(parse.GetValue(scale))),
            SelectionOptions.ParseJobs(parse.GetValue(jobs)),
            parse.GetValue(quiet),
            parse.GetValue(incremental),
            FormatOption.Parse(parse.GetValue(format))));
        return command;
    }

    private static int Run(CliConsole console, BatchSelection selection, string? datPath, string? cellPath, string outDir,
        ShapeBuildOptions options, int jobs, bool quiet, bool incremental, OutputFormats formats)
    {
        var clock = Stopwatch.StartNew();
        if (File.Exists(outDir))
            throw new CliException(ExitCodes.OutputFailed, $"--out: {outDir} is a file: pass a folder (it is created when missing)");
        using var dat = DatLocator.Open(datPath, cellPath, console);
        var plan = SelectionOptions.Plan(selection, dat);
        OutputFolder.Prepare(outDir);
        var engine = new ExportEngine(dat.Portal, options);
        var inputs = new BatchInputs(dat.Portal.Info, selection.Landblock is null ? null : dat.Cell?.Info, options.Policy, options.EntityScale, selection)
        {
            Formats = formats,
        };

        var progress = new ProgressReporter(console.Error, console.IsTerminal, quiet, "setups");
        BatchResult result;
        try
        {
            result = BatchRunner.Run(engine, plan, inputs, jobs, progress.Report);
        }
        finally
        {
            progress.Finish();
        }

        var exported = clock.Elapsed;
        OutputFolder.RefuseForeignFiles(outDir, result.Files.Select(f => (f.RelativePath, f.Content)).Append((BatchResult.IndexPath, result.IndexJson)),
            OutputFolder.ListedByIndex(outDir));
        var writing = new ProgressReporter(console.Error, console.IsTerminal, quiet, "files written");
        int filesWritten, unchanged;
        long written;
        try
        {
            (filesWritten, unchanged, written) = Write(outDir, result, incremental, jobs, writing.Report);
        }
        finally
        {
            writing.Finish();
        }

        var o = console.Out;
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"batch {selection.Describe()} from {dat.Description} ({options.Policy.Name()}, scale {options.EntityScale}): " +
            $"{result.SetupsWritten} setup(s), {result.BspDumps} GfxObj BSP dump(s), {result.Scenes} scene(s)"));
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  files: {filesWritten} written ({written} bytes){(incremental ? $", {unchanged} unchanged and left alone" : "")}, index {Path.Combine(outDir, BatchResult.IndexPath)}"));
        foreach (var group in result.Skipped.GroupBy(s => (s.Reason, From: string.Join(", ", s.From.Names()))))
            o.WriteLine($"  skipped {group.Count()} ({group.Key.Reason}; from {group.Key.From}): {string.Join(' ', group.Select(s => JsonIds.Format(s.Id)))}");
        if (result.Diagnostics.Count > 0)
            o.WriteLine($"  diagnostics: {result.Diagnostics.Count} in {result.Diagnostics.Select(d => d.Id).Distinct().Count()} setup(s) (listed in each file's \"diagnostics\")");
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wall time {clock.Elapsed.TotalSeconds:0.000} s with {jobs} job(s) (dat and export {exported.TotalSeconds:0.000} s, writing {(clock.Elapsed - exported).TotalSeconds:0.000} s)"));
        return ExitCodes.Ok;
    }

    /// <summary>
    /// Files in parallel (each atomically, so order does not matter), then index.json last: an index on
    /// disk only ever describes files already written.
    /// </summary>
    private static (int Written, int Unchanged, long Bytes) Write(string outDir, BatchResult result, bool incremental, int jobs,
        Action<BatchProgress> progress)
    {
        int filesWritten = 0, unchanged = 0, done = 0;
        long bytes = 0;
        var total = result.Files.Count + 1;
        void WriteOne(string path, byte[] content)
        {
            if (incremental && OutputFolder.IsUnchanged(outDir, path, content)) Interlocked.Increment(ref unchanged);
            else
            {
                Interlocked.Add(ref bytes, OutputFolder.WriteAtomically(outDir, path, content));
                Interlocked.Increment(ref filesWritten);
            }
            progress(new BatchProgress(Interlocked.Increment(ref done), total));
        }
        try
        {
            Parallel.ForEach(result.Files, new ParallelOptions { MaxDegreeOfParallelism = jobs }, f => WriteOne(f.RelativePath, f.Content));
        }
        catch (AggregateException e) when (e.InnerExceptions.OfType<CliException>().FirstOrDefault() is { } first)
        {
            throw first;
        }
        WriteOne(BatchResult.IndexPath, result.IndexJson);
        return (filesWritten, unchanged, bytes);
    }
}
