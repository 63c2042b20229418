using AcShadow.Cli.Infrastructure;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// A run's files written through the one <see cref="AtomicFile"/> (not flushed: a batch writes tens of
/// thousands of files that are cheap to make again; docs/errors.md says what a power cut may leave), with
/// a failure turned into the output error line (exit 6).
/// </summary>
public static class AtomicOutput
{
    public static long Write(string root, string relativePath, ReadOnlyMemory<byte> content) =>
        Guarded(root, OutputPaths.Target(root, relativePath), target => AtomicFile.Write(target, content.Span, Durability.Renamed))!.Value;

    /// <summary>For content <paramref name="write"/> streams in large chunks.</summary>
    public static long Write(string root, string relativePath, Action<Stream> write) =>
        Guarded(root, OutputPaths.Target(root, relativePath), target => AtomicFile.Write(target, write, Durability.Renamed))!.Value;

    /// <summary>
    /// A file where nothing is expected (<see cref="AtomicFile.WriteNew"/>): the bytes written, or null when
    /// something is at the path, which is then left as it is.
    /// </summary>
    public static long? WriteNew(string root, string relativePath, ReadOnlyMemory<byte> content) =>
        Guarded(root, OutputPaths.Target(root, relativePath), target => AtomicFile.WriteNew(target, content.Span, Durability.Renamed));

    private static long? Guarded(string root, string target, Func<string, long?> write)
    {
        // The run's ledger (when it keeps one) knows each write in flight, so a signal can stop the run
        // without leaving its temporary file, and counts what was written whole.
        var ledger = OutputLedger.Current;
        var full = Path.GetFullPath(target);
        ledger?.Begin(full);
        long? written = null;
        try
        {
            written = write(target);
            return written;
        }
        catch (NotARegularFileException e)
        {
            throw new CliException(ExitCodes.OutputFailed, $"--out: {e.Message}; move it away or pass another folder");
        }
        // The folder moved or deleted under the run, whichever step of the write met it first.
        catch (IOException) when (!Directory.Exists(root))
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {target}: folder {root} is gone (moved or deleted while this run wrote into it): the output is incomplete, run again");
        }
        // With SIGXFSZ handled (Program), a write past the file-size limit fails with EFBIG, which .NET reports
        // as ArgumentOutOfRangeException ("Specified file length was too large").
        catch (ArgumentOutOfRangeException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {target}: File too large: past the file-size limit (ulimit -f) or the file system's largest file");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {target}: {e.Message} (check --out points at a writable folder with free space)");
        }
        finally
        {
            ledger?.End(root, full, written);
        }
    }
}
