using AcShadow.Cli.Infrastructure;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// A file the user names outright (audit's --out FILE), treated as a shell redirection would: a regular
/// file (or none) is replaced atomically; a device, FIFO or socket (--out /dev/stdout, a named pipe) is
/// written into, never replaced; a symbolic link is written through, so the link stays and the file it
/// leads to gets the report.
/// </summary>
public static class ExplicitOutputFile
{
    /// <summary>Before the dat is read: the path names a file, not a folder.</summary>
    public static void Check(string path, string example)
    {
        OutputPaths.RequireNamed(path, "--out", "a file name", example);
        if (Directory.Exists(path))
            throw new CliException(ExitCodes.OutputFailed, $"--out: {path} is a folder: pass a file name, e.g. {example}");
    }

    /// <summary>
    /// Once the dats are open: the path is none of them (by device and inode, so a link or another spelling
    /// of the path counts). A proprietary dat replaced by a report cannot be had back.
    /// </summary>
    public static void RefuseInput(string path, OpenedDat dat, string example)
    {
        if (dat.Reads(path))
            throw new CliException(ExitCodes.OutputFailed, $"--out: {path} is a dat this run reads: acshadow never writes over its input; pass another file name, e.g. {example}");
    }

    public static void Write(string path, byte[] content, string example = "audit.csv")
    {
        OutputPaths.RequireNamed(path, "--out", "a file name", example);
        var full = Path.GetFullPath(path);
        var kind = FileKinds.Of(full);
        try
        {
            if (kind is FileKind.Missing or FileKind.Regular or FileKind.Unknown)
            {
                // The folder's lock, as every folder-writing command takes it: a report is not written into a
                // folder another run is writing (a folder that does not exist yet has no such run).
                var folder = Path.GetDirectoryName(full)!;
                using var held = Directory.Exists(folder) ? OutputFolderLock.Acquire(folder) : null;
                AtomicOutput.Write(folder, Path.GetFileName(full), content);
                return;
            }
            if (FileKinds.Of(full, followLinks: true) is var target && target is FileKind.Folder or FileKind.Missing)
                throw new CliException(ExitCodes.OutputFailed, target == FileKind.Folder
                    ? $"--out: {path} leads to a folder: pass a file name, e.g. {example}"
                    : $"--out: {path} is a symbolic link that leads nowhere (or round in a loop): pass a file name, e.g. {example}");
            using var stream = new FileStream(full, FileMode.Create, FileAccess.Write, FileShare.ReadWrite, bufferSize: 0);
            stream.Write(content);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {path}: {e.Message}");
        }
    }
}
