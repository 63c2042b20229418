using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Formats;

namespace AcShadow.Cli.Output;

/// <summary>
/// The folder a run writes into, and the one order every folder-writing command (dump, batch, chart,
/// scene, view) takes its steps in: the path is checked before any work (<see cref="Check"/>); the folder
/// is made and a file written in it, then locked against a second writer, and what killed runs left is
/// removed (<see cref="Open"/>); files acshadow does not own are refused before the first write
/// (<see cref="RefuseForeign"/>); each file is written whole (<see cref="Write(string, ReadOnlyMemory{byte})"/>);
/// and the folder must still be the one locked before the run says it succeeded (<see cref="RequireStillInPlace"/>).
/// </summary>
public sealed class OutputFolder : IDisposable
{
    private const string Option = "--out";
    private readonly OutputFolderLock _lock;

    private OutputFolder(string root, OutputFolderLock held)
    {
        Root = root;
        _lock = held;
    }

    public string Root { get; }

    /// <summary>Before the dat is read: an empty path, or a file where the folder belongs, fails in a second rather than after the work.</summary>
    public static void Check(string root)
    {
        OutputPaths.RequireNamed(root, Option);
        if (File.Exists(root))
            throw new CliException(ExitCodes.OutputFailed, $"{Option}: {root} is a file: pass a folder (it is created when missing)");
    }

    /// <summary>The folder made (when missing), shown writable, held, and rid of abandoned temporaries; nothing of this run is written yet.</summary>
    public static OutputFolder Open(string root)
    {
        WriteProbe.Prepare(root, Option);
        var held = OutputFolderLock.Acquire(root, Option);
        AbandonedTemporaries.Remove(root);
        return new OutputFolder(root, held);
    }

    /// <summary>Refuses the run, naming them, when any of these files exists and is not acshadow's (or, listed, the folder's index says it is).</summary>
    public void RefuseForeign(IEnumerable<OutputFile> files, IReadOnlySet<string>? listedAsOurs = null) =>
        ForeignFileGuard.Refuse(Root, files, listedAsOurs, Option);

    /// <summary>Whether the file already holds exactly these bytes (then it is left alone: its timestamp kept, no new inode).</summary>
    public bool IsUnchanged(string relativePath, ReadOnlySpan<byte> content) => UnchangedCheck.IsUnchanged(Root, relativePath, content);

    /// <summary>Writes one file whole; the bytes written.</summary>
    public long Write(string relativePath, ReadOnlyMemory<byte> content) => AtomicOutput.Write(Root, relativePath, content);

    /// <summary>Writes one file whole from content <paramref name="write"/> streams in large chunks; the bytes written.</summary>
    public long Write(string relativePath, Action<Stream> write) => AtomicOutput.Write(Root, relativePath, write);

    /// <summary>
    /// Writes each file, saying so on <paramref name="log"/>, except one that already holds exactly its bytes
    /// (no rewrite, its timestamp kept so build tools and git see no change, and no replace-by-rename that
    /// frees an inode); the files' total size.
    /// </summary>
    public long WriteEach(IEnumerable<OutputFile> files, TextWriter log, CancellationToken interrupted)
    {
        long bytes = 0;
        foreach (var (path, content) in files)
        {
            interrupted.ThrowIfCancellationRequested();
            if (IsUnchanged(path, content.Span))
                log.WriteLine($"unchanged {Path.Combine(Root, path)} ({content.Length} bytes, already these bytes)");
            else
            {
                Write(path, content);
                log.WriteLine($"wrote {Path.Combine(Root, path)} ({content.Length} bytes)");
            }
            bytes += content.Length;
        }
        return bytes;
    }

    /// <summary>Fails (exit 6) when the folder at the path is no longer the one this run locked and wrote into.</summary>
    public void RequireStillInPlace() => _lock.RequireStillInPlace();

    public void Dispose() => _lock.Dispose();
}
