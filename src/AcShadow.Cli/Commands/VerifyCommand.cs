using System.CommandLine;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Batch;
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

    /// <summary>
    /// The folders batch writes, as the file formats place their files (setups/, gfxobjs/, cells/): files in
    /// them that regeneration does not produce are "extra".
    /// </summary>
    private static readonly string[] OutputFolders =
        [.. FileFormats.All.Select(f => f.PathPattern).Where(p => p.Contains('/')).Select(p => p[..p.IndexOf('/')]).Distinct()];

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
        using var dat = DatLocator.Open(datPath, cellPath, console);
        var selection = recorded.Selection;
        if (selection.Landblock is { } lb && dat.Cell is null)
            throw new CliException(ExitCodes.Usage, $"the fixtures hold the scene of landblock {LandblockIds.Short(lb)}: pass --cell-dat PATH (client_cell_1.dat) with --dat");

        var plan = SelectionOptions.Plan(selection, dat);
        var options = recorded.BuildOptions();
        var cellInfo = selection.Landblock is null ? null : dat.Cell?.Info;
        var inputs = recorded with { Dat = dat.Portal.Info, CellDat = cellInfo };
        var result = BatchRunner.Run(dat.Portal, options, plan, inputs, jobs, cancellation: console.Interrupted);
        dat.RequireUnchanged();

        var expected = result.AllFiles.ToDictionary(f => f.RelativePath, f => f.Content, StringComparer.Ordinal);
        var actual = ReadFolder(folder, index);
        var datDifferences = FixtureComparer.DatDifferences("dat", recorded.Dat, dat.Portal.Info)
            .Concat(FixtureComparer.DatDifferences("cell dat", recorded.CellDat, cellInfo)).ToArray();
        var comparison = FixtureComparer.Compare(expected, actual, datDifferences);
        return Report(console, folder, dat.Description, comparison);
    }

    private static BatchIndex ReadIndex(string folder)
    {
        if (!Directory.Exists(folder))
            throw new CliException(ExitCodes.Usage, $"--fixtures: {folder} is not a folder: pass the folder `acshadow batch --out` wrote");
        var path = Path.Combine(folder, FileFormats.Index.Path);
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

    /// <summary>index.json, every file under the folders batch writes, and any other file the index lists.</summary>
    private static Dictionary<string, byte[]> ReadFolder(string folder, BatchIndex index)
    {
        var files = new Dictionary<string, byte[]>(StringComparer.Ordinal);
        void Add(string relative)
        {
            var full = Path.Combine(folder, relative.Replace('/', Path.DirectorySeparatorChar));
            if (!files.ContainsKey(relative) && FileKinds.Of(full, followLinks: true) != FileKind.Missing) files[relative] = ReadFixture(folder, relative);
        }
        Add(FileFormats.Index.Path);
        Add(FileFormats.Scene.Path);
        foreach (var sub in OutputFolders)
        {
            var dir = Path.Combine(folder, sub);
            if (!Directory.Exists(dir)) continue;
            foreach (var file in Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories))
            {
                if (file.EndsWith(".tmp", StringComparison.Ordinal)) continue; // an interrupted write's leftover
                Add(Path.GetRelativePath(folder, file).Replace(Path.DirectorySeparatorChar, '/'));
            }
        }
        // Only paths inside the folder: an index is data, not a licence to read elsewhere.
        foreach (var listed in index.Files.Where(f => !Path.IsPathRooted(f.Path) && !f.Path.Split('/', '\\').Contains("..")))
            Add(listed.Path);
        return files;
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

    /// <summary>Whether the folder holds files a batch writes (its subfolders' JSON), index aside.</summary>
    private static bool HasOutput(string folder) =>
        OutputFolders.Any(sub => Directory.Exists(Path.Combine(folder, sub))
            && Directory.EnumerateFiles(Path.Combine(folder, sub), "*.json", SearchOption.AllDirectories).Any());

    private static int Report(CliConsole console, string folder, string source, FixtureComparison c)
    {
        var o = console.Out;
        if (c.IsIdentical)
        {
            o.WriteLine($"verify: {folder} matches a fresh regeneration from {source} ({c.Compared} file(s), index.json included)");
            return ExitCodes.Ok;
        }
        foreach (var d in c.DatDifferences) o.WriteLine($"dat differs from the one index.json records: {d}");
        foreach (var changed in c.Changed)
        {
            if (changed.OnlyLineEndings)
            {
                o.WriteLine($"changed {changed.Path}: line endings differ (CRLF): the same bytes once CRLF is read as LF (a checkout converted them; keep fixtures exact with `fixtures/** -text` in .gitattributes)");
                continue;
            }
            if (changed.Reason is { } reason)
            {
                o.WriteLine($"changed {changed.Path}: {reason}");
                continue;
            }
            o.WriteLine($"changed {changed.Path}");
            if (changed.Differences is null)
            {
                o.WriteLine("  (not JSON on one side: the bytes differ)");
                continue;
            }
            foreach (var d in changed.Differences.Take(MaxDifferencesShown)) o.WriteLine($"  {changed.Path}: {d}");
            if (changed.Differences.Count > MaxDifferencesShown)
                o.WriteLine($"  … and {changed.Differences.Count - MaxDifferencesShown} more difference(s) in {changed.Path}");
        }
        foreach (var path in c.Missing) o.WriteLine($"missing {path} (regeneration writes it; {folder} lacks it)");
        foreach (var path in c.Extra) o.WriteLine($"extra {path} ({folder} has it; regeneration does not write it)");
        console.Error.WriteLine(
            $"acshadow: {folder} drifted: {c.Changed.Count} changed{(c.Changed.Count(f => f.OnlyLineEndings) is > 0 and var crlf ? (crlf == c.Changed.Count ? " (line endings differ (CRLF) only)" : $" ({crlf} in line endings (CRLF) only)") : "")}, {c.Missing.Count} missing, {c.Extra.Count} extra file(s)" +
            (c.DatDifferences.Count > 0 ? ", a different dat" : "") +
            " — if the change is intended, regenerate the fixtures: run `acshadow batch` into the folder again with the inputs its index.json records");
        return ExitCodes.Drift;
    }
}
