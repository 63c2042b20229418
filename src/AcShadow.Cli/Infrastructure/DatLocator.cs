using System.Runtime.CompilerServices;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Files;
using AcShadow.Forging;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Finds the dat: --dat (the file, or a folder holding client_portal.dat), else ACSHADOW_DAT, else the
/// built-in forged sample, opened from memory through the same reader a retail dat goes through. The cell
/// dat: --cell-dat, else ACSHADOW_CELL_DAT, else client_cell_1.dat in the folder --dat (or ACSHADOW_DAT)
/// names, opened when a command first needs cells.
/// A dat's directory is read as lookups need it; a command that lists ids (batch, audit, doctor, verify) walks
/// it whole at open (<c>wholeDirectory</c>), so damage anywhere in it is refused before anything is written.
/// </summary>
public static class DatLocator
{
    public const string EnvironmentVariable = "ACSHADOW_DAT";
    public const string CellEnvironmentVariable = "ACSHADOW_CELL_DAT";
    public const string PortalFileName = "client_portal.dat";
    public const string CellFileName = "client_cell_1.dat";

    /// <summary>"{source}: {file} is not a readable dat: " for each dat file opened, for a damaged directory found later.</summary>
    private static readonly ConditionalWeakTable<DatArchive, string> Refusals = new();

    /// <summary>
    /// The line for directory damage a lookup (or a later walk) met: the same as had the dat been refused at open.
    /// </summary>
    public static string Describe(DatDirectoryException e) =>
        Refusals.TryGetValue(e.Archive, out var prefix) ? prefix + e.Message : $"corrupt dat: {e.Message}";

    public static OpenedDat Open(string? datOption, string? cellDatOption, CliConsole console, bool wholeDirectory = false)
    {
        var watches = new List<DatFileWatch>();
        var cellSource = cellDatOption is null ? CellEnvironmentVariable : "--cell-dat";
        cellDatOption ??= NullIfEmpty(console.Environment(CellEnvironmentVariable));
        var portalPath = datOption ?? NullIfEmpty(console.Environment(EnvironmentVariable));
        if (portalPath is null)
        {
            console.Error.WriteLine("acshadow: no --dat and no ACSHADOW_DAT: using the built-in SYNTHETIC sample data (forged, not retail).");
            var (portalBytes, cellBytes) = SampleDats.Build();
            var samplePortal = OpenBytes(portalBytes, "sample/" + PortalFileName);
            var sampleCell = cellDatOption is null && cellBytes is not null ? OpenBytes(cellBytes, "sample/" + CellFileName) : null;
            var cellFromOption = cellDatOption is null ? null : OpenFile(cellDatOption, CellFileName, cellSource, DatFileKind.Cell, watches, wholeDirectory);
            return new OpenedDat(samplePortal, cellFromOption ?? sampleCell, "the built-in synthetic sample", true, watches);
        }
        var source = datOption is null ? EnvironmentVariable : "--dat";
        var portal = OpenFile(portalPath, PortalFileName, source, DatFileKind.Portal, watches, wholeDirectory);
        try
        {
            var cell = cellDatOption is null ? null : OpenFile(cellDatOption, CellFileName, cellSource, DatFileKind.Cell, watches, wholeDirectory);
            // A folder holding both dats (the client's own folder) gives the cell dat too.
            var beside = cell is null && Directory.Exists(portalPath) && File.Exists(Path.Combine(portalPath, CellFileName)) ? portalPath : null;
            return new OpenedDat(portal, cell, portal.Archive.Name, false, watches,
                beside is null ? null : (Path.Combine(beside, CellFileName), () => OpenFile(beside, CellFileName, source, DatFileKind.Cell, watches, wholeDirectory)));
        }
        catch
        {
            portal.Dispose();
            throw;
        }
    }

    private static string? NullIfEmpty(string? s) => string.IsNullOrWhiteSpace(s) ? null : s;

    private static DatDatabase OpenBytes(byte[] bytes, string name) => DatDatabase.Open(new MemoryStream(bytes, writable: false), name);

    private static DatDatabase OpenFile(string path, string expectedName, string source, DatFileKind expectedKind, List<DatFileWatch> watches, bool wholeDirectory)
    {
        var file = Directory.Exists(path) ? Path.Combine(path, expectedName) : path;
        // Links are followed (a dat kept elsewhere and linked in is the common case); what they lead to is checked.
        var kind = FileKinds.Of(file, followLinks: true);
        if (kind == FileKind.Missing && FileKinds.Of(file) == FileKind.SymbolicLink)
            throw new CliException(ExitCodes.DatUnreadable, LinkProblem(file, source, expectedName));
        if (kind == FileKind.Folder)
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: {file} is a folder, not a file: pass the path of your {expectedName}");
        if (kind == FileKind.Missing)
            throw new CliException(ExitCodes.DatUnreadable, Directory.Exists(path)
                ? $"{source}: folder {path} has no {expectedName}: pass the dat file itself or the folder that holds it"
                : $"{source}: {path} does not exist: pass the path of your {expectedName} (or the folder holding it)");
        // Checked before opening: opening a FIFO would wait for a writer forever, and a device has no length.
        InputFile.RequireRegular(file, kind, ExitCodes.DatUnreadable, source, $"pass your {expectedName} (a dat is read at random places, so it cannot be streamed)");
        var length = new FileInfo(file).ResolveLinkTarget(returnFinalTarget: true) is FileInfo target ? target.Length : new FileInfo(file).Length;
        if (length < DatHeader.Size)
            throw new CliException(ExitCodes.DatUnreadable,
                $"{source}: {file} is {length} bytes, too short for a dat (or not a regular file): every dat starts with a {DatHeader.Size}-byte header; pass your {expectedName}");
        FileStream stream;
        try
        {
            stream = new FileStream(file, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.RandomAccess);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: cannot open {file}: {e.Message}");
        }
        DatDatabase dat;
        var refusal = $"{source}: {file} is not a readable dat: ";
        try
        {
            dat = DatDatabase.Open(stream, Path.GetFileName(file));
        }
        catch (Exception e) when (e is DatFormatException or DatDirectoryException)
        {
            throw new CliException(ExitCodes.DatUnreadable, refusal + e.Message);
        }
        catch (IOException e)
        {
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: cannot read {file}: {e.Message}");
        }
        Refusals.AddOrUpdate(dat.Archive, refusal);
        if (wholeDirectory)
        {
            try
            {
                _ = dat.Archive.Entries;
            }
            catch (DatDirectoryException e)
            {
                dat.Dispose();
                throw new CliException(ExitCodes.DatUnreadable, refusal + e.Message);
            }
        }
        watches.Add(new DatFileWatch(file, stream));
        // The header's data set says which database this is; a swapped pair would otherwise read as empty.
        // Undefined is let through: a dat whose header does not say is tried rather than refused.
        var datKind = dat.Archive.Header.Kind;
        if (datKind != expectedKind && datKind != DatFileKind.Undefined)
        {
            dat.Dispose();
            throw new CliException(ExitCodes.DatUnreadable, KindName(datKind) is { } name
                ? $"{source}: {file} is {name} dat, not {KindName(expectedKind)} dat (its header says so): pass {expectedName} there"
                : $"{source}: {file} is not a readable dat: its header names data set {(uint)datKind}, which is no dat acshadow knows (1 portal, 2 cell, 3 language)");
        }
        return dat;
    }

    /// <summary>A link that leads nowhere: a loop (said in words) or a missing target (named).</summary>
    private static string LinkProblem(string file, string source, string expectedName)
    {
        var seen = new HashSet<string>(StringComparer.Ordinal);
        var current = Path.GetFullPath(file);
        // One link at a time (40 is the kernel's own limit): a path met twice is a loop.
        for (var hop = 0; hop < 40 && FileKinds.Of(current) == FileKind.SymbolicLink; hop++)
        {
            if (!seen.Add(current)) break;
            var target = new FileInfo(current).LinkTarget!;
            current = Path.GetFullPath(target, Path.GetDirectoryName(current)!);
        }
        return FileKinds.Of(current) == FileKind.SymbolicLink
            ? $"{source}: {file} is a symbolic link loop (following it leads back to {current}, never to a file): pass the path of your {expectedName}"
            : $"{source}: {file} is a symbolic link to {current}, which does not exist: pass the path of your {expectedName}";
    }

    private static string? KindName(DatFileKind kind) => kind switch
    {
        DatFileKind.Portal => "a portal",
        DatFileKind.Cell => "a cell",
        DatFileKind.Local => "a language (client_local_English)",
        _ => null,
    };
}
