using Microsoft.Win32.SafeHandles;

namespace AcShadow.Files;

/// <summary>
/// Writes a file whole or not at all, for every tool of the repository: the bytes go to <c>NAME.PID.tmp</c>
/// beside the target (same folder, so same file system, so the rename is atomic), which is then renamed over
/// the target. A killed process leaves the old file or the new one, whole, and at most a <c>.tmp</c> whose
/// process id says it was abandoned. Whether the bytes are flushed to the disk first is the caller's
/// <see cref="Durability"/>. Only a regular file (or nothing) is replaced: a device, FIFO, socket, symbolic
/// link or folder at the target is a <see cref="NotARegularFileException"/>, and nothing is written.
/// </summary>
public static class AtomicFile
{
    public const string TemporarySuffix = ".tmp";

    /// <summary>The temporary name a write of <paramref name="target"/> by this process uses.</summary>
    public static string TemporaryFor(string target) => $"{target}.{Environment.ProcessId}{TemporarySuffix}";

    // The temporary's name is the process's, not the thread's (so a later run can tell an abandoned one, and a
    // stopped run can remove its own): two threads writing one target must take turns, or one truncates, deletes
    // or renames into place the other's half-written file. Each target has a turn of its own, kept while a write
    // of it is in flight, so writes of different targets never wait on each other. Turns shared by targets whose
    // hashes met deadlocked chart --jobs 2: chart.csv's streamed write held its turn while its callback waited for
    // a worker, and the worker's failure map waited for that same turn.
    private static readonly Dictionary<string, Turn> Turns = new(StringComparer.Ordinal);
    private static readonly Lock TurnsGuard = new();

    /// <summary>One target's turn and how many writes of it hold it or wait for it (read and changed under <see cref="TurnsGuard"/>).</summary>
    private sealed class Turn
    {
        public readonly Lock Lock = new();
        public int Writers;
    }

    /// <summary>A turn taken; disposing gives it back, and forgets it when no other write of the target waits.</summary>
    private readonly struct HeldTurn(string fullPath, Turn turn) : IDisposable
    {
        public void Dispose()
        {
            turn.Lock.Exit();
            lock (TurnsGuard)
                if (--turn.Writers == 0) Turns.Remove(fullPath);
        }
    }

    /// <summary>Waits for the target's turn (a thread may take its own again: the lock is reentrant).</summary>
    private static HeldTurn TakeTurn(string fullPath)
    {
        Turn? turn;
        lock (TurnsGuard)
        {
            if (!Turns.TryGetValue(fullPath, out turn)) Turns.Add(fullPath, turn = new Turn());
            turn.Writers++;
        }
        turn.Lock.Enter();
        return new HeldTurn(fullPath, turn);
    }

    /// <summary>Writes <paramref name="content"/> to <paramref name="path"/>; returns its length.</summary>
    public static long Write(string path, ReadOnlySpan<byte> content, Durability durability)
    {
        var full = Path.GetFullPath(path);
        RequireReplaceable(full);
        var temp = TemporaryFor(full);
        using var turn = TakeTurn(full);
        try
        {
            WriteTemporary(temp, content, durability);
            Replace(temp, full);
            return content.Length;
        }
        catch
        {
            TryDelete(temp);
            throw;
        }
    }

    /// <summary>
    /// Writes <paramref name="content"/> to <paramref name="path"/> where nothing is expected to be, the same way
    /// (temporary file, then rename), but without looking at the path first: on Linux the rename itself refuses
    /// to replace anything (<c>renameat2</c> with <c>RENAME_NOREPLACE</c>), so whatever is there (a file, a link,
    /// a FIFO) stays as it is and the temporary file is removed. Returns the length written, or null when
    /// something was there: the caller then decides, with <see cref="Write(string, ReadOnlySpan{byte}, Durability)"/>'s
    /// checks, whether to replace it. For a run writing many new files into one folder: every look at a name
    /// not yet in the folder takes the folder's lock in the kernel, which a second writer then waits for.
    /// </summary>
    public static long? WriteNew(string path, ReadOnlySpan<byte> content, Durability durability)
    {
        var full = Path.GetFullPath(path);
        var temp = TemporaryFor(full);
        using var turn = TakeTurn(full);
        try
        {
            WriteTemporary(temp, content, durability);
            var moved = ExclusiveRename.Move(temp, full);
            // A platform or file system that cannot rename without replacing: a look, then the rename Write makes.
            if (moved is null && FileKinds.Of(full) == FileKind.Missing)
            {
                Replace(temp, full);
                moved = true;
            }
            if (moved == true) return content.Length;
            TryDelete(temp);
            return null;
        }
        catch
        {
            TryDelete(temp);
            throw;
        }
    }

    /// <summary>The bytes in a new temporary file, flushed when <paramref name="durability"/> says so.</summary>
    private static void WriteTemporary(string temp, ReadOnlySpan<byte> content, Durability durability)
    {
        using var handle = CreateTemporary(temp);
        // One positional write: no stream buffer, seek or truncate of a file just created (a batch
        // writes tens of thousands). Not File.WriteAllBytes: it preallocates the length first, and a
        // file the file system cannot hold then fails as an ArgumentException, not the write's I/O error.
        RandomAccess.Write(handle, content, 0);
        if (durability == Durability.Flushed) RandomAccess.FlushToDisk(handle);
    }

    /// <summary>As <see cref="Write(string, ReadOnlySpan{byte}, Durability)"/>, for content <paramref name="write"/> streams (in large chunks: the stream is unbuffered).</summary>
    public static long Write(string path, Action<Stream> write, Durability durability)
    {
        var full = Path.GetFullPath(path);
        RequireReplaceable(full);
        var temp = TemporaryFor(full);
        using var turn = TakeTurn(full);
        try
        {
            long length;
            using (var handle = CreateTemporary(temp))
            {
                using (var stream = new FileStream(handle, FileAccess.Write, bufferSize: 0))
                {
                    write(stream);
                    length = stream.Position;
                }
                if (durability == Durability.Flushed) RandomAccess.FlushToDisk(handle);
            }
            Replace(temp, full);
            return length;
        }
        catch
        {
            TryDelete(temp);
            throw;
        }
    }

    /// <summary>Throws <see cref="NotARegularFileException"/> unless <paramref name="path"/> is missing or a regular file.</summary>
    public static void RequireReplaceable(string path)
    {
        var kind = FileKinds.Of(path);
        if (kind is not (FileKind.Missing or FileKind.Regular or FileKind.Unknown)) throw new NotARegularFileException(path, kind);
    }

    /// <summary>The check again right before the rename: a FIFO or link put there while the bytes were written is not replaced either.</summary>
    private static void Replace(string temp, string target)
    {
        RequireReplaceable(target);
        File.Move(temp, target, overwrite: true);
    }

    /// <summary>
    /// The temporary file, created new (nothing to truncate). Its folder is made when missing, but not the
    /// folder above it: a destination whose parent vanished (moved or deleted while a run writes) is an
    /// error, not something to recreate. One left by an earlier process that had this process's id is replaced.
    /// </summary>
    private static SafeFileHandle CreateTemporary(string temp)
    {
        try
        {
            return File.OpenHandle(temp, FileMode.CreateNew, FileAccess.Write, FileShare.Read);
        }
        // ENOENT: the folder is missing. .NET names it a missing file instead when another thread created
        // the folder between the failed open and the error's mapping, so both mean "make the folder".
        catch (IOException e) when (e is DirectoryNotFoundException or FileNotFoundException)
        {
            var folder = Path.GetDirectoryName(temp)!;
            var above = Path.GetDirectoryName(folder);
            if (above is not null && !Directory.Exists(above))
                throw new DirectoryNotFoundException($"folder {above} is gone (moved or deleted while this run wrote into it)");
            Directory.CreateDirectory(folder);
        }
        catch (IOException) when (File.Exists(temp))
        {
            File.Delete(temp);
        }
        return File.OpenHandle(temp, FileMode.CreateNew, FileAccess.Write, FileShare.Read);
    }

    private static void TryDelete(string path)
    {
        try { if (File.Exists(path)) File.Delete(path); } catch (IOException) { } catch (UnauthorizedAccessException) { }
    }
}
