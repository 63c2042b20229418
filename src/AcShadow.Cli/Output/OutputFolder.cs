using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Formats;
using AcShadow.Files;

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
    private readonly OpenedDat? _reads;

    private OutputFolder(string root, OutputFolderLock held, OpenedDat? reads, bool startedEmpty)
    {
        Root = root;
        _lock = held;
        _reads = reads;
        StartedEmpty = startedEmpty;
    }

    public string Root { get; }

    /// <summary>
    /// The folder was missing or empty when this run opened it (it holds the run's lock now): no file in it can
    /// be foreign or a dat, so the checks of every path a run will write can be skipped.
    /// </summary>
    public bool StartedEmpty { get; }

    /// <summary>Before the dat is read: an empty path, or a file where the folder belongs, fails in a second rather than after the work.</summary>
    public static void Check(string root)
    {
        OutputPaths.RequireNamed(root, Option);
        if (File.Exists(root))
            throw new CliException(ExitCodes.OutputFailed, $"{Option}: {root} is a file: pass a folder (it is created when missing)");
    }

    /// <summary>
    /// The folder made (when missing), shown writable, held, and rid of abandoned temporaries; nothing of this
    /// run is written yet. A link (or a file) where one of the folders a run writes in belongs is refused
    /// here, before anything is written. <paramref name="reads"/>: the dats this run reads, which no write
    /// may replace.
    /// </summary>
    public static OutputFolder Open(string root, OpenedDat? reads = null)
    {
        var startedEmpty = FileKinds.Of(root) == FileKind.Missing || (FileKinds.Of(root) == FileKind.Folder && !Directory.EnumerateFileSystemEntries(root).Any());
        WriteProbe.Prepare(root, Option);
        var held = OutputFolderLock.Acquire(root, Option);
        try
        {
            OutputPaths.RequireSubfoldersInside(root);
        }
        catch
        {
            held.Dispose();
            throw;
        }
        AbandonedTemporaries.Remove(root);
        return new OutputFolder(root, held, reads, startedEmpty);
    }

    /// <summary>
    /// Refuses the run, naming them, when any of these files is a dat the run reads, or exists and is not
    /// acshadow's (or, listed, the folder's index says it is).
    /// </summary>
    public void RefuseForeign(IEnumerable<OutputFile> files, IReadOnlySet<string>? listedAsOurs = null)
    {
        var all = files as IReadOnlyCollection<OutputFile> ?? files.ToArray();
        RefuseInputs(all.Select(f => f.RelativePath), "; nothing was written");
        ForeignFileGuard.Refuse(Root, all, listedAsOurs, Option);
    }

    /// <summary>
    /// Refuses the run when one of these paths names (by any link or spelling) a dat it reads: a file the
    /// folder's own index lists is replaced without a look at its content, and a dat put there would be lost.
    /// </summary>
    public void RefuseInputs(IEnumerable<string> relativePaths, string said = "")
    {
        if (_reads is null) return;
        foreach (var relative in relativePaths)
        {
            var target = OutputPaths.Target(Root, relative);
            if (_reads.Reads(target)) throw ReadsInput(target, said);
        }
    }

    /// <summary>
    /// What is at each path, refusing the run as <see cref="RefuseInputs"/> does when one names a dat it reads:
    /// one look at each path (a link's target is looked at too), where asking its kind and then whether it is an
    /// input took three: a batch surveys every path it plans before writing (29,000 on the 7,000-Setup scale
    /// dat), and those looks were a fifth of an incremental run with nothing to do.
    /// </summary>
    public FileKind[] Survey(IReadOnlyList<string> relativePaths, string said)
    {
        var targets = OutputPaths.Targets(Root, relativePaths);
        var inputs = _reads?.ReadIdentities() ?? [];
        var kinds = new FileKind[targets.Length];
        for (var i = 0; i < targets.Length; i++)
        {
            var (kind, identity) = FileKinds.Look(targets[i]);
            kinds[i] = kind;
            var isInput = kind == FileKind.SymbolicLink
                ? _reads?.Reads(targets[i]) == true
                : identity is not null && OpenedDat.IsOneOf(identity, inputs);
            if (isInput) throw ReadsInput(targets[i], said);
        }
        return kinds;
    }

    private CliException ReadsInput(string target, string said) =>
        new(ExitCodes.OutputFailed, $"{Option}: {target} is a dat this run reads: acshadow never writes over its input; move the dat out of {Root} or pass another folder{said}");

    /// <summary>Whether the file already holds exactly these bytes (then it is left alone: its timestamp kept, no new inode).</summary>
    public bool IsUnchanged(string relativePath, ReadOnlySpan<byte> content) => UnchangedCheck.IsUnchanged(Root, relativePath, content);

    /// <summary>Writes one file whole; the bytes written.</summary>
    public long Write(string relativePath, ReadOnlyMemory<byte> content)
    {
        RefuseInputs([relativePath]);
        return AtomicOutput.Write(Root, relativePath, content);
    }

    /// <summary>
    /// Writes one file whole where nothing is expected to be, without looking first (<see cref="AtomicFile.WriteNew"/>):
    /// the bytes written, or null when something is at the path, left as it is: the caller then asks
    /// <see cref="IsUnchanged"/> and <see cref="Write(string, ReadOnlyMemory{byte})"/> as for any file. No dat this run
    /// reads can be lost here: nothing that exists is replaced.
    /// </summary>
    public long? WriteNew(string relativePath, ReadOnlyMemory<byte> content) => AtomicOutput.WriteNew(Root, relativePath, content);

    /// <summary>Writes one file whole from content <paramref name="write"/> streams in large chunks; the bytes written.</summary>
    public long Write(string relativePath, Action<Stream> write)
    {
        RefuseInputs([relativePath]);
        return AtomicOutput.Write(Root, relativePath, write);
    }

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

    /// <summary>
    /// Removes a file an earlier run wrote that this run does not (<paramref name="because"/> says why it
    /// goes, for the error line): only a regular file inside the folder; a link, a folder or nothing there is
    /// left alone. <paramref name="beforeRemoving"/> runs first. Whether a file was removed.
    /// </summary>
    public bool RemoveEarlier(string relativePath, string because, Action? beforeRemoving = null)
    {
        var path = OutputPaths.Target(Root, relativePath);
        if (FileKinds.Of(path) != FileKind.Regular) return false;
        beforeRemoving?.Invoke();
        try
        {
            File.Delete(path);
            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot remove {path} ({because}): {e.Message}");
        }
    }

    /// <summary>Fails (exit 6) when the folder at the path is no longer the one this run locked and wrote into.</summary>
    public void RequireStillInPlace() => _lock.RequireStillInPlace();

    public void Dispose() => _lock.Dispose();
}
