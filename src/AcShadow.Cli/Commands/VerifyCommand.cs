using System.CommandLine;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli.Output;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Shapes;
using AcShadow.Core.Verify;
using AcShadow.Files;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow verify --fixtures DIR`: regenerate in memory what DIR/index.json describes, with its
/// inputs, through the same engine batch uses, and compare file by file. Exit 0 when identical, 5 on
/// drift (missing, extra or changed files, or a different dat).
/// </summary>
public static class VerifyCommand
{
    /// <summary>At most this many JSON differences are printed per file.</summary>
    public const int MaxDifferencesShown = 20;

    public static Command Create(CliConsole console)
    {
        var fixtures = new Option<string>("--fixtures") { Description = "a folder batch wrote (it holds index.json)", HelpName = "DIR", Required = true };
        var dat = CommonOptions.Dat();
        var cellDat = new Option<string?>("--cell-dat") { Description = "client_cell_1.dat (or its folder), when the fixtures hold a scene", HelpName = "PATH" };
        var jobs = SelectionOptions.Jobs();
        var command = new Command("verify", "Check that a fixtures folder still matches what the dat gives (exit 5 on drift)")
        {
            fixtures, dat, cellDat, jobs,
        };
        command.SetAction(parse => Run(console, parse.GetValue(fixtures)!, parse.GetValue(dat), parse.GetValue(cellDat),
            SelectionOptions.WorkersOrAllCores(parse, jobs)));
        return command;
    }

    private static int Run(CliConsole console, string folder, string? datPath, string? cellPath, int jobs)
    {
        var index = ReadIndex(folder);
        var recorded = index.Inputs;
        using var dat = DatLocator.Open(datPath, cellPath, console, wholeDirectory: true);
        var selection = recorded.Selection;
        if (selection.Landblock is { } lb && dat.Cell is null)
            throw new CliException(ExitCodes.Usage, $"the fixtures hold the scene of landblock {LandblockIds.Short(lb)}: pass --cell-dat PATH (client_cell_1.dat) with --dat");

        var plan = SelectionOptions.Plan(selection, dat);
        var options = recorded.BuildOptions();
        var portalInfo = Identity(recorded.Dat, dat.Portal);
        var cellInfo = selection.Landblock is null || dat.Cell is null ? null : Identity(recorded.CellDat, dat.Cell);
        var inputs = recorded with { Dat = portalInfo, CellDat = cellInfo };
        var result = BatchRunner.Run(dat.Portal, options, plan, inputs, jobs, cancellation: console.Interrupted);
        dat.RequireUnchanged();

        var expected = result.AllFiles.ToDictionary(f => f.RelativePath, f => f.Content, StringComparer.Ordinal);
        var (actual, links) = ReadFolder(folder, index);
        var datDifferences = FixtureComparer.DatDifferences("dat", recorded.Dat, portalInfo)
            .Concat(FixtureComparer.DatDifferences("cell dat", recorded.CellDat, cellInfo)).ToArray();
        var comparison = FixtureComparer.Compare(expected, actual, datDifferences);
        return Report(console, folder, dat.Description, comparison, links);
    }

    /// <summary>
    /// The dat at hand as the regenerated index records it. When index.json recorded a content hash and this
    /// dat has the same one, it is the same dat whatever its name, and the recorded identity stands (so the
    /// fixtures a sample made verify against that sample forged to disk). An index from before hashes is
    /// regenerated as it was written: without one.
    /// </summary>
    private static DatSourceInfo Identity(DatSourceInfo? recorded, DatDatabase current)
    {
        if (recorded?.Sha256 is null) return current.Info;
        var hashed = OpenedDat.Hashed(current);
        return hashed.Sha256 == recorded.Sha256 ? recorded : hashed;
    }

    private static BatchIndex ReadIndex(string folder)
    {
        if (!Directory.Exists(folder))
            throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} is not a folder: pass the folder `acshadow batch --out` wrote");
        var path = Path.Combine(folder, FileFormats.Index.Path);
        if (FileKinds.Of(path) == FileKind.SymbolicLink)
            throw new CliException(ExitCodes.Usage, $"--fixtures: {path} is a symbolic link (to {FolderLinks.TargetOf(path)}): verify reads no file through a link (a fixtures folder holds the files batch wrote): pass the folder the index is in");
        if (FileKinds.Of(path, followLinks: true) == FileKind.Missing)
        {
            // A batch removes the old index before its first write and writes the new one last, so output
            // without an index is a run that was stopped before it finished, or what `dump` writes (no index):
            // either way nothing says what the files should be, which is a usage error, not drift.
            if (HasOutput(folder))
                throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} has no {FileFormats.Index.Path}, so it is no finished batch: it holds acshadow output (what `dump` writes, or an incomplete run: a batch stopped before the end); verify checks what `acshadow batch --out` wrote: run the batch into it first");
            throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} has no {FileFormats.Index.Path}: pass a folder `acshadow batch --out` wrote");
        }
        var bytes = ReadFixture(folder, FileFormats.Index.Path);
        // An editor that saved index.json with a byte-order mark: said as such, not as "not an index".
        if (bytes.AsSpan().StartsWith("\uFEFF"u8))
            throw new CliException(ExitCodes.Usage, $"--fixtures: {path} starts with a UTF-8 byte-order mark (an editor added it; acshadow writes none): remove the mark or run the batch again");
        try
        {
            return BatchIndexReader.Read(bytes);
        }
        catch (FormatException e)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: {path} is not a batch index: {e.Message}");
        }
    }

    /// <summary>A symbolic link met in the fixtures folder: its path in the folder, and the line that reports it.</summary>
    private sealed record FoundLink(string Path, string Line);

    /// <summary>
    /// index.json, every file under the folders batch writes, and any other file the index lists, by their
    /// paths in the folder; and the links met on the way. Nothing is read through a link or walked into
    /// through one: a link is reported once, as a link (a loop named as such), and what it leads to is never
    /// opened, so no file outside the folder reaches the report.
    /// </summary>
    private static (Dictionary<string, byte[]> Files, IReadOnlyList<FoundLink> Links) ReadFolder(string folder, BatchIndex index)
    {
        var files = new Dictionary<string, byte[]>(StringComparer.Ordinal);
        var links = new SortedDictionary<string, FoundLink>(StringComparer.Ordinal);
        bool Linked(string relative)
        {
            if (FolderLinks.FirstDetour(folder, relative, includeLast: true) is not { Kind: FileKind.SymbolicLink } detour) return false;
            var at = Path.GetRelativePath(folder, detour.Path).Replace(Path.DirectorySeparatorChar, '/');
            links.TryAdd(at, new FoundLink(at, LinkLine(at, detour.Path)));
            return true;
        }
        void Add(string relative)
        {
            if (files.ContainsKey(relative) || Linked(relative)) return;
            var full = Path.Combine(folder, relative.Replace('/', Path.DirectorySeparatorChar));
            if (FileKinds.Of(full) != FileKind.Missing) files[relative] = ReadFixture(folder, relative);
        }
        void Walk(string relative)
        {
            if (Linked(relative)) return;
            var full = Path.Combine(folder, relative.Replace('/', Path.DirectorySeparatorChar));
            if (FileKinds.Of(full) != FileKind.Folder) return;
            foreach (var entry in Directory.EnumerateFileSystemEntries(full).Order(StringComparer.Ordinal))
            {
                var child = relative + "/" + Path.GetFileName(entry);
                if (FileKinds.Of(entry) == FileKind.Folder) Walk(child);
                else if (!entry.EndsWith(".tmp", StringComparison.Ordinal)) Add(child); // a .tmp: an interrupted write's leftover
            }
        }
        Add(FileFormats.Index.Path);
        Add(FileFormats.Scene.Path);
        foreach (var sub in OutputPaths.Subfolders) Walk(sub);
        // Only paths inside the folder: an index is data, not a licence to read elsewhere.
        foreach (var listed in index.Files.Where(f => RelativeOutputPath.StaysInside(f.Path)))
            Add(listed.Path);
        return (files, links.Values.ToArray());
    }

    /// <summary>How a link is reported: where it leads as written, and whether it leads back into the folder (a loop).</summary>
    private static string LinkLine(string relative, string full)
    {
        var target = FolderLinks.TargetOf(full) ?? "?";
        var parent = Path.GetDirectoryName(Path.GetFullPath(full))!;
        var resolved = Path.GetFullPath(target, parent);
        var loop = resolved == Path.GetFullPath(full)
            || (parent + Path.DirectorySeparatorChar).StartsWith(resolved.TrimEnd(Path.DirectorySeparatorChar) + Path.DirectorySeparatorChar, StringComparison.Ordinal);
        return loop
            ? $"link {relative} -> {target} (a symbolic link loop: it leads back into the folder; not followed)"
            : $"link {relative} -> {target} (a symbolic link: a fixtures folder holds only the files batch wrote, and verify reads nothing through a link; not followed)";
    }

    /// <summary>
    /// A fixture's bytes; one that cannot be read (permissions, a FIFO or device where a file belongs, which
    /// would block or never end) is a bad fixtures folder, named, not an internal error.
    /// </summary>
    private static byte[] ReadFixture(string folder, string relative)
    {
        var full = Path.Combine(folder, relative.Replace('/', Path.DirectorySeparatorChar));
        InputFile.RequireRegular(full, ExitCodes.Usage, "--fixtures", "a fixtures folder holds only the files batch wrote");
        InputFile.RequireAtMost(full, InputFile.MaxFixtureBytes, ExitCodes.Usage, "--fixtures");
        try
        {
            return File.ReadAllBytes(full);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.Usage, $"--fixtures: cannot read {full}: {e.Message} (a fixtures folder must be readable)");
        }
    }

    /// <summary>Whether the folder holds files a batch writes (JSON in its subfolders, which are not links), index aside.</summary>
    private static bool HasOutput(string folder) =>
        OutputPaths.Subfolders.Any(sub => FileKinds.Of(Path.Combine(folder, sub)) == FileKind.Folder
            && Directory.EnumerateFiles(Path.Combine(folder, sub), "*.json", SearchOption.TopDirectoryOnly).Any());

    private static int Report(CliConsole console, string folder, string source, FixtureComparison c, IReadOnlyList<FoundLink> links)
    {
        var o = console.Out;
        var shownFolder = PrintableText.Escape(folder);
        if (c.IsIdentical && links.Count == 0)
        {
            o.WriteLine($"verify: {shownFolder} matches a fresh regeneration from {source} ({c.Compared} file(s), index.json included)");
            return ExitCodes.Ok;
        }
        // Names and values come from the disk: every one is escaped before it reaches the terminal.
        static string P(string text) => PrintableText.Escape(text);
        foreach (var d in c.DatDifferences) o.WriteLine($"dat differs from the one index.json records: {P(d)}");
        foreach (var changed in c.Changed)
        {
            if (changed.OnlyLineEndings)
            {
                o.WriteLine($"changed {P(changed.Path)}: line endings differ (CRLF): the same bytes once CRLF is read as LF (a checkout converted them; keep fixtures exact with `fixtures/** -text` in .gitattributes)");
                continue;
            }
            if (changed.Reason is { } reason)
            {
                o.WriteLine($"changed {P(changed.Path)}: {reason}");
                continue;
            }
            o.WriteLine($"changed {P(changed.Path)}");
            if (changed.Differences is null)
            {
                o.WriteLine("  (not JSON on one side: the bytes differ)");
                continue;
            }
            foreach (var d in changed.Differences.Take(MaxDifferencesShown)) o.WriteLine($"  {P(changed.Path)}: {P(d.ToString())}");
            if (changed.Differences.Count > MaxDifferencesShown)
                o.WriteLine($"  … and {changed.Differences.Count - MaxDifferencesShown} more difference(s) in {P(changed.Path)}");
        }
        // A fixture that is a link is reported as the link, not also as missing.
        var linked = links.Select(l => l.Path).ToHashSet(StringComparer.Ordinal);
        var missing = c.Missing.Where(p => !linked.Contains(p)).ToArray();
        foreach (var path in missing) o.WriteLine($"missing {P(path)} (regeneration writes it; {shownFolder} lacks it)");
        foreach (var path in c.Extra) o.WriteLine($"extra {P(path)} ({shownFolder} has it; regeneration does not write it)");
        foreach (var link in links) o.WriteLine(P(link.Line));
        console.Error.WriteLine(
            $"acshadow: {shownFolder} drifted: {c.Changed.Count} changed{(c.Changed.Count(f => f.OnlyLineEndings) is > 0 and var crlf ? (crlf == c.Changed.Count ? " (line endings differ (CRLF) only)" : $" ({crlf} in line endings (CRLF) only)") : "")}, {missing.Length} missing, {c.Extra.Count} extra file(s)" +
            (links.Count > 0 ? $", {links.Count} symbolic link(s) not followed" : "") +
            (c.DatDifferences.Count > 0 ? ", a different dat" : "") +
            " — if the change is intended, regenerate the fixtures: run `acshadow batch` into the folder again with the inputs its index.json records");
        return ExitCodes.Drift;
    }
}
