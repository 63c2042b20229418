using AcShadow.Core.Dat;
using AcShadow.Forge;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Finds the dat: --dat (the file, or a folder holding client_portal.dat), else ACSHADOW_DAT, else the
/// built-in forged sample, opened from memory through the same reader a retail dat goes through.
/// </summary>
public static class DatLocator
{
    public const string EnvironmentVariable = "ACSHADOW_DAT";
    public const string PortalFileName = "client_portal.dat";
    public const string CellFileName = "client_cell_1.dat";

    public static OpenedDat Open(string? datOption, string? cellDatOption, CliConsole console)
    {
        var portalPath = datOption ?? NullIfEmpty(console.Environment(EnvironmentVariable));
        if (portalPath is null)
        {
            console.Error.WriteLine("acshadow: no --dat and no ACSHADOW_DAT: using the built-in SYNTHETIC sample data (forged, not retail).");
            var (portalBytes, cellBytes) = SampleDats.Build();
            var samplePortal = OpenBytes(portalBytes, "sample/" + PortalFileName);
            var sampleCell = cellDatOption is null && cellBytes is not null ? OpenBytes(cellBytes, "sample/" + CellFileName) : null;
            var cellFromOption = cellDatOption is null ? null : OpenFile(cellDatOption, CellFileName, "--cell-dat", DatFileKind.Cell);
            return new OpenedDat(samplePortal, cellFromOption ?? sampleCell, "the built-in synthetic sample", true);
        }
        var source = datOption is null ? EnvironmentVariable : "--dat";
        var portal = OpenFile(portalPath, PortalFileName, source, DatFileKind.Portal);
        try
        {
            var cell = cellDatOption is null ? null : OpenFile(cellDatOption, CellFileName, "--cell-dat", DatFileKind.Cell);
            return new OpenedDat(portal, cell, portal.Archive.Name, false);
        }
        catch
        {
            portal.Dispose();
            throw;
        }
    }

    private static string? NullIfEmpty(string? s) => string.IsNullOrWhiteSpace(s) ? null : s;

    private static DatDatabase OpenBytes(byte[] bytes, string name) => DatDatabase.Open(new MemoryStream(bytes, writable: false), name);

    private static DatDatabase OpenFile(string path, string expectedName, string source, DatFileKind expectedKind)
    {
        var file = Directory.Exists(path) ? Path.Combine(path, expectedName) : path;
        if (Directory.Exists(file))
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: {file} is a folder, not a file: pass the path of your {expectedName}");
        if (!File.Exists(file))
            throw new CliException(ExitCodes.DatUnreadable, Directory.Exists(path)
                ? $"{source}: folder {path} has no {expectedName}: pass the dat file itself or the folder that holds it"
                : $"{source}: {path} does not exist: pass the path of your {expectedName} (or the folder holding it)");
        // Checked before opening: a FIFO or a device reports no length, and opening a FIFO would wait forever.
        var length = new FileInfo(file).Length;
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
        try
        {
            dat = DatDatabase.Open(stream, Path.GetFileName(file));
        }
        catch (DatFormatException e)
        {
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: {file} is not a readable dat: {e.Message}");
        }
        catch (IOException e)
        {
            throw new CliException(ExitCodes.DatUnreadable, $"{source}: cannot read {file}: {e.Message}");
        }
        // The header's data set says which database this is; a swapped pair would otherwise read as empty.
        // Undefined is let through: a dat whose header does not say is tried rather than refused.
        var kind = dat.Archive.Header.Kind;
        if (kind != expectedKind && kind != DatFileKind.Undefined)
        {
            dat.Dispose();
            throw new CliException(ExitCodes.DatUnreadable, KindName(kind) is { } name
                ? $"{source}: {file} is {name} dat, not {KindName(expectedKind)} dat (its header says so): pass {expectedName} there"
                : $"{source}: {file} is not a readable dat: its header names data set {(uint)kind}, which is no dat acshadow knows (1 portal, 2 cell, 3 language)");
        }
        return dat;
    }

    private static string? KindName(DatFileKind kind) => kind switch
    {
        DatFileKind.Portal => "a portal",
        DatFileKind.Cell => "a cell",
        DatFileKind.Local => "a language (client_local_English)",
        _ => null,
    };
}
