using AcShadow.Cli.Infrastructure;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// Before any work is done: the output folder exists or is created, and a file can be created in it, so a
/// folder that cannot take output fails in a second, not after the export.
/// </summary>
public static class WriteProbe
{
    /// <summary>The probe's name; its temporary form is one of ours, so a killed probe is cleaned up like any other.</summary>
    public const string Name = ".acshadow-write-test";

    public static void Prepare(string root, string option = "--out")
    {
        OutputPaths.RequireNamed(root, option);
        var kind = FileKinds.Of(root, followLinks: true);
        if (kind is not (FileKind.Missing or FileKind.Folder or FileKind.Unknown))
            throw new CliException(ExitCodes.OutputFailed, kind == FileKind.Regular
                ? $"{option}: {root} is a file: pass a folder (it is created when missing)"
                : $"{option}: {root} is {FileKinds.Describe(kind)}: pass a folder (it is created when missing)");
        try
        {
            Directory.CreateDirectory(root);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"{option}: cannot create folder {root}: {e.Message} (pass a folder you can write to)");
        }
        var probe = Path.Combine(root, AtomicFile.TemporaryFor(Name));
        try
        {
            File.WriteAllBytes(probe, [0]);
            File.Delete(probe);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            try { File.Delete(probe); } catch (IOException) { } catch (UnauthorizedAccessException) { }
            throw new CliException(ExitCodes.OutputFailed, $"{option}: cannot write in folder {root}: {e.Message} (pass a folder you can write to)");
        }
    }
}
