using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Security.Cryptography;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Poses;
using AcShadow.Core.Scenes;
using AcShadow.Core.Shapes;
using AcShadow.Files;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow batch --out DIR [selection]`: many Setups (and a landblock's scene) through the one export
/// engine, in parallel, written atomically with index.json; skipped ids are reported, never fatal.
/// </summary>
public static class BatchCommand
{
    /// <summary>
    /// Decoded objects the dat keeps for each job: a Setup's parts are read for its shapes and again for their
    /// BSP dumps, so a few Setups' worth. More only keeps objects alive long enough to be copied through the
    /// collector's generations: on the 3,000-Setup scale dat, 256 in all (the old size) took 1.77 s at one job and
    /// 1.31 s at two, 16 a job 1.38 and 0.94 s, with a quarter less memory (docs/performance.md, issue 30).
    /// </summary>
    public const int WorkingSetPerJob = 16;

    public static Command Create(CliConsole console)
    {
        var selection = new SelectionOptions();
        var dat = CommonOptions.Dat();
        var outDir = CommonOptions.RequiredOut();
        var policy = CommonOptions.Policy();
        var scale = CommonOptions.Scale();
        var jobs = SelectionOptions.Jobs();
        var quiet = new Option<bool>("--quiet") { Description = "no progress display (the summary is still printed)" };
        var incremental = new Option<bool>("--incremental") { Description = "skip Setups whose dat bytes (and their parts') did not change since the last --incremental run into DIR, and leave files whose content would not change untouched" };
        var format = FormatOption.Create();
        var pose = new PoseOptions();
        var cells = new Option<bool>("--cells") { Description = "with --landblock: also write its indoor cells (the default)" };
        var noCells = new Option<bool>("--no-cells") { Description = "with --landblock: objects only, no indoor cells" };
        var movement = MoveCommand.MovementOption();
        var mover = MoveCommand.MoverOption();
        var command = new Command("batch", "Export many Setups (door catalog, all, a list, a landblock's scene) with index.json")
        {
            outDir, dat, selection.CellDat, selection.Doors, selection.All, selection.Setups, selection.Landblock,
            cells, noCells, policy, scale, jobs, quiet, incremental, format, movement, mover,
        };
        foreach (var option in pose.All) command.Options.Add(option);
        command.SetAction(parse => Run(console,
            WithCells(selection.Parse(parse, defaultToAll: false), parse.GetValue(cells), parse.GetValue(noCells)),
            parse.GetValue(dat),
            parse.GetValue(selection.CellDat),
            parse.GetValue(outDir)!,
            pose.Apply(parse, new ShapeBuildOptions(parse.GetValue(policy) ?? ShapePolicy.Retail, parse.GetValue(scale) ?? 1f)),
            SelectionOptions.WorkersOrAllCores(parse, jobs),
            parse.GetValue(quiet),
            parse.GetValue(incremental),
            parse.GetValue(format) ?? OutputFormats.Canonical,
            parse.GetValue(movement) ?? [], parse.GetValue(mover)));
        return command;
    }

    private static BatchSelection WithCells(BatchSelection selection, bool cells, bool noCells)
    {
        if (cells && noCells) throw new CliException(ExitCodes.Usage, "--cells and --no-cells contradict each other: give one");
        if ((cells || noCells) && selection.Landblock is null) throw new CliException(ExitCodes.Usage, $"{(cells ? "--cells" : "--no-cells")} applies to a landblock's scene: add --landblock 0xXXYY");
        return selection with { Cells = !noCells };
    }

    private static int Run(CliConsole console, BatchSelection selection, string? datPath, string? cellPath, string outDir,
        ShapeBuildOptions options, int jobs, bool quiet, bool incremental, OutputFormats formats, uint[] movementIds, uint? moverId)
    {
        var clock = Stopwatch.StartNew();
        OutputFolder.Check(outDir);
        using var dat = DatLocator.Open(datPath, cellPath, console, wholeDirectory: true);
        var plan = SelectionOptions.Plan(selection, dat);
        PoseOptions.RequireUsable(options, dat.Portal, plan.Setups.Select(s => s.Id).ToArray());
        var movement = MoveCommand.Selection(movementIds, moverId, dat);
        using var folder = OutputFolder.Open(outDir, dat);
        // The portal dat's SHA-256 (index.json records it) reads the whole file once more: with a second job it is
        // read beside the export, not before it, where it was the largest part of the run no second core shortens.
        var portalHash = jobs > 1 ? Task.Run(() => OpenedDat.Hashed(dat.Portal)) : Task.FromResult(OpenedDat.Hashed(dat.Portal));
        var inputs = new BatchInputs(dat.Portal.Info, selection.Landblock is null || dat.Cell is null ? null : OpenedDat.Hashed(dat.Cell), options.Policy, options.EntityScale, selection)
        {
            Formats = formats,
            Pose = options.Pose,
            DoorState = options.DoorState,
            MotionTable = options.MotionTable,
            Movement = movement,
        };
        // The last state is read (megabytes on a retail dat) beside the survey of the folder when there is a second core.
        var lastState = !incremental ? null : jobs > 1 ? Task.Run(() => ReadState(outDir)) : Task.FromResult(ReadState(outDir));
        var previous = RefuseForeignFiles(folder, plan, formats);
        // Decoded objects are kept only while in use (a bounded working set): memory does not grow with the dat.
        var source = dat.PortalWorkingSet(WorkingSetPerJob * jobs);
        var last = lastState?.GetAwaiter().GetResult();
        // Fingerprints (every object read again and hashed) only when the state they feed is written.
        var reuse = incremental
            ? new BatchReuse(last?.State, IncrementalState.ToolKey(options, formats), dat.Portal.Archive.ReadObjectBytes, file => HoldsRecordedBytes(outDir, file))
            : null;

        int filesWritten = 0, unchanged = 0, indexRemoved = 0;
        long written = 0;
        // A file that already holds exactly its bytes is left alone: a re-run keeps timestamps and, on ext4,
        // avoids replacing a file, whose freed inode every later create in the next minute steps over.
        void Write(string path, ReadOnlyMemory<byte> content)
        {
            // Into a folder that was empty (this run holds its lock and writes each path once) a file goes in
            // without a look at its path first: each look at a name not yet in a folder takes the folder's lock
            // in the kernel, and with two jobs on a disk file system the other job's creates and renames queue
            // behind it (docs/performance.md). Whatever is there after all stays, and takes the way below.
            if (folder.StartedEmpty)
            {
                if (Interlocked.Exchange(ref indexRemoved, 1) == 0) RemoveIndex(outDir);
                if (folder.WriteNew(path, content) is { } bytes)
                {
                    Interlocked.Add(ref written, bytes);
                    Interlocked.Increment(ref filesWritten);
                    return;
                }
            }
            if (folder.IsUnchanged(path, content.Span)) Interlocked.Increment(ref unchanged);
            else
            {
                // An index describes a finished run: the old one goes before the first file changes, so a run
                // stopped part-way leaves a folder verify calls incomplete, not an index its files contradict.
                if (Interlocked.Exchange(ref indexRemoved, 1) == 0) RemoveIndex(outDir);
                Interlocked.Add(ref written, folder.Write(path, content));
                Interlocked.Increment(ref filesWritten);
            }
        }

        var progress = new ProgressReporter(console.Error, console.IsTerminal, quiet, "setups", "batch");
        BatchSummary result;
        try
        {
            result = BatchRunner.Stream(source, options, plan, inputs, jobs, f => Write(f.RelativePath, f.Content), reuse, p =>
            {
                progress.Report(p);
                dat.RequireUnchangedNowAndThen();
            }, console.Interrupted);
            result = result with { Inputs = result.Inputs with { Dat = portalHash.GetAwaiter().GetResult() } };
            dat.RequireUnchanged();
        }
        catch (OperationCanceledException) when (console.Interrupted.IsCancellationRequested)
        {
            throw Interrupted(outDir, filesWritten, written);
        }
        // A dat cut or rewritten under the run shows up as any read error: that is the error to report.
        catch (Exception e) when (e is AggregateException or IOException or DatFormatException)
        {
            dat.RequireUnchanged();
            if (e is AggregateException a && a.InnerExceptions.OfType<CliException>().FirstOrDefault() is { } first) throw first;
            throw;
        }
        finally
        {
            progress.Finish();
        }
        folder.RequireStillInPlace();
        // What the previous run wrote and this one did not (cells after --no-cells, Setups no longer chosen)
        // goes before the new index, so the index never sits beside files no run of its inputs writes.
        var removed = RemoveStale(folder, previous, result.Files, () =>
        {
            if (Interlocked.Exchange(ref indexRemoved, 1) == 0) RemoveIndex(outDir);
        });
        // The state for the next --incremental run, then index.json, last: an index on disk only ever
        // describes files already written.
        // A state that is the last one itself, whose file still holds the bytes read, is left alone unserialised:
        // writing a retail state again only to find it unchanged was a sixth of an incremental run with nothing to do.
        if (incremental && !(last is { AsWritten: true } kept && result.State.IsUnchangedFrom(kept.State)
                && HoldsBytes(outDir, IncrementalState.Path, kept.Bytes, kept.Sha256)))
            Write(IncrementalState.Path, IncrementalStateFile.Write(result.State));
        if (incremental) Write(FileFormats.Index.Path, result.IndexJson());
        else
        {
            // Streamed to its file: on a retail dat index.json is megabytes, and a buffer for it would be the
            // run's largest allocation, at its very end.
            written += folder.Write(FileFormats.Index.Path, result.WriteIndex);
            filesWritten++;
        }
        folder.RequireStillInPlace();
        // Files of Setups reused unseen are unchanged too.
        if (incremental) unchanged = result.Files.Count + 2 - filesWritten;

        var o = console.Out;
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"batch {selection.Describe()} from {dat.Description} ({options.Policy.Name()}, {options.Pose.Name()} pose, scale {options.EntityScale}): " +
            $"{result.SetupsWritten} setup(s), {result.BspDumps} GfxObj BSP dump(s), {result.Scenes} scene(s){(result.Cells > 0 ? $", {result.Cells} cell(s)" : "")}"));
        var reused = incremental ? $", {result.SetupsReused} setup(s) unchanged in the dat and not re-exported" : "";
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  files: {filesWritten} written ({written} bytes){(incremental || unchanged > 0 ? $", {unchanged} unchanged and left alone" : "")}{reused}{(removed > 0 ? $", {removed} removed (the previous run wrote them; this run does not)" : "")}, index {Path.Combine(outDir, FileFormats.Index.Path)}"));
        foreach (var group in result.Skipped.GroupBy(s => (s.Reason, From: string.Join(", ", s.From.Names()))))
            o.WriteLine($"  skipped {group.Count()} ({group.Key.Reason}; from {group.Key.From}): {IdSummary.Of(group.Select(s => s.Id).ToArray())}{(group.Count() > IdSummary.Shown ? " (all in index.json's skipped)" : "")}");
        if (result.Diagnostics.Diagnostics > 0)
            o.WriteLine($"  diagnostics: {result.Diagnostics.Diagnostics} in {result.Diagnostics.Setups} setup(s) (listed in each file's \"diagnostics\")");
        o.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  wall time {clock.Elapsed.TotalSeconds:0.000} s with {jobs} job(s)"));
        return ExitCodes.Ok;
    }

    /// <summary>
    /// Files stream to disk as they are made, so the check that no file acshadow does not own gets replaced
    /// runs first, over what is already there: every file in the places a batch writes (the planned Setups'
    /// shadow files, gfxobjs/, scene.json, cells/, index.json, incremental.json) that the folder's index.json does
    /// not list must carry the signature of the acshadow format its name stands for.
    /// </summary>
    /// <returns>The files the folder's index.json lists (the previous run's).</returns>
    private static IReadOnlySet<string> RefuseForeignFiles(OutputFolder folder, BatchPlan plan, OutputFormats formats)
    {
        var outDir = folder.Root;
        // A folder that was empty holds nothing to refuse (and no index): on a first run that is a look at every planned path saved.
        if (folder.StartedEmpty) return new HashSet<string>(StringComparer.Ordinal);
        var listed = IndexListing.Read(outDir);
        // Each path with the head a file of its format starts with, made only for the few that need a look inside.
        var planned = new List<(string Relative, Func<OutputFile> Candidate)>();
        void Consider(string relative, string format) => planned.Add((relative, () => new OutputFile(relative, ForeignFileGuard.JsonHead(format).ToArray())));
        void ConsiderText(string relative, string head) => planned.Add((relative, () => OutputFile.Text(relative, head)));
        foreach (var setup in plan.Setups) Consider(FileFormats.Shadow.PathFor(setup.Id), FileFormats.Shadow.Format);
        var gfxobjs = Path.Combine(outDir, "gfxobjs");
        if (Directory.Exists(gfxobjs))
            foreach (var file in Directory.EnumerateFiles(gfxobjs, "*.json").Order(StringComparer.Ordinal))
            {
                var relative = "gfxobjs/" + Path.GetFileName(file);
                if (relative.EndsWith(".bsp.json", StringComparison.Ordinal)) Consider(relative, FileFormats.Bsp.Format);
                else if (relative.EndsWith(".gfxobj.json", StringComparison.Ordinal)) ConsiderText(relative, "{\n  \"GfxObjId\": 0,\n");
            }
        if (plan.Scene is not null) Consider(FileFormats.Scene.Path, FileFormats.Scene.Format);
        foreach (var cell in plan.Scene?.Cells ?? [])
        {
            Consider(FileFormats.Cell.PathFor(cell.Id), FileFormats.Cell.Format);
            if (formats.HasFlag(OutputFormats.Acdream)) ConsiderText(FileFormats.AcdreamCell.PathFor(cell.Id), "{\n  \"CellId\": 0,\n");
        }
        Consider(FileFormats.Index.Path, FileFormats.Index.Format);
        Consider(IncrementalState.Path, IncrementalState.Format);
        // A listed file is replaced unread: one that is the dat this run reads is refused first.
        var kinds = folder.Survey([.. planned.Select(p => p.Relative)], "; nothing was written");
        // A file the index lists is ours even when damaged; anything but a regular file never is.
        var candidates = new List<OutputFile>();
        for (var i = 0; i < planned.Count; i++)
            if (kinds[i] switch { FileKind.Missing => false, FileKind.Regular => !listed.Contains(planned[i].Relative), _ => true })
                candidates.Add(planned[i].Candidate());
        folder.RefuseForeign(candidates, listed);
        return listed;
    }

    /// <summary>
    /// Removes the files the previous run's index listed that this run did not write (only regular files at
    /// paths inside the folder); <paramref name="beforeFirst"/> runs before the first removal. The count removed.
    /// </summary>
    private static int RemoveStale(OutputFolder folder, IReadOnlySet<string> previous, IReadOnlyList<FileEntry> written, Action beforeFirst)
    {
        var kept = written.Select(f => f.RelativePath).Append(FileFormats.Index.Path).Append(IncrementalState.Path).ToHashSet(StringComparer.Ordinal);
        return previous.Where(p => !kept.Contains(p) && RelativeOutputPath.StaysInside(p)).Order(StringComparer.Ordinal)
            .Count(relative => folder.RemoveEarlier(relative, "the previous run wrote it and this one does not", beforeFirst));
    }

    private static void RemoveIndex(string outDir)
    {
        var index = Path.Combine(outDir, FileFormats.Index.Path);
        try
        {
            if (FileKinds.Of(index) == FileKind.Regular) File.Delete(index);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot remove the previous run's {index} before replacing its files: {e.Message}");
        }
    }

    /// <summary>Ctrl-C: what is on disk, and that the folder is not a finished run (it has no index.json).</summary>
    private static CliException Interrupted(string outDir, int files, long bytes) =>
        new(ExitCodes.Interrupted, string.Create(CultureInfo.InvariantCulture,
            $"{Interrupt.Word}: {files} file(s) ({bytes} bytes) were written to {outDir}, each whole; the folder is incomplete (no index.json, so verify calls it an incomplete run): run the same batch again to complete it"));

    /// <summary>Whether a file the previous run wrote still holds exactly the bytes it recorded (<see cref="FileDigest.Holds"/>), inside the folder.</summary>
    private static bool HoldsRecordedBytes(string outDir, FileEntry file) => HoldsBytes(outDir, file.RelativePath, file.Bytes, file.Sha256);

    private static bool HoldsBytes(string outDir, string relativePath, long bytes, string sha256) =>
        FileDigest.Holds(OutputPaths.Target(outDir, relativePath), bytes, sha256);

    /// <summary>
    /// The last state read: whether its file carries its checksum as the writer lays it out (<see cref="IncrementalStateFile.TryRead(byte[], out bool)"/>),
    /// and the file's size and SHA-256, to tell later that it still holds those bytes.
    /// </summary>
    private sealed record LastState(IncrementalState State, bool AsWritten, long Bytes, string Sha256);

    /// <summary>The previous run's incremental.json, or null when there is none or it is unreadable (then everything is exported).</summary>
    private static LastState? ReadState(string outDir)
    {
        var path = Path.Combine(outDir, IncrementalState.Path);
        try
        {
            // A regular file only: a link (or a FIFO) is not this folder's state.
            if (FileKinds.Of(path) != FileKind.Regular) return null;
            var bytes = File.ReadAllBytes(path);
            return IncrementalStateFile.TryRead(bytes, out var asWritten) is { } state
                ? new LastState(state, asWritten, bytes.Length, Convert.ToHexStringLower(SHA256.HashData(bytes)))
                : null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }
}
