using System.Runtime.InteropServices;

namespace AcShadow.Files;

/// <summary>
/// One writer per folder: an exclusive OS lock (flock on Unix, LockFileEx on Windows) on
/// <c>FOLDER/.acshadow.lock</c>, held for as long as this object lives. The OS drops it when the process
/// ends however it ends, so a killed run leaves no stale lock, at most an empty file. The folder's identity
/// (device and inode) is noted when locked, so <see cref="StillInPlace"/> tells whether the folder at the
/// path is still the one locked, not moved, deleted or replaced since.
/// </summary>
public sealed class FolderLock : IDisposable
{
    public const string FileName = ".acshadow.lock";

    private readonly FileStream _stream;
    private readonly byte[]? _folderIdentity;

    public string Folder { get; }

    private FolderLock(string folder, FileStream stream, byte[]? folderIdentity)
    {
        Folder = folder;
        _stream = stream;
        _folderIdentity = folderIdentity;
    }

    /// <summary>The lock, or null when another process (or another run in this one) holds it.</summary>
    public static FolderLock? TryAcquire(string folder)
    {
        var path = Path.Combine(folder, FileName);
        // A holder that released and deleted the file between our open and our lock leaves us holding a
        // lock on a file no longer at the path: check, and try again on the file now there.
        for (var attempt = 0; attempt < 8; attempt++)
        {
            FileStream stream;
            try
            {
                stream = new FileStream(path, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.ReadWrite | FileShare.Delete, 1, FileOptions.None);
            }
            // Where .NET takes a lock of its own on open (unless the app turns it off), a held lock refuses the open.
            catch (IOException) when (File.Exists(path))
            {
                return null;
            }
            if (!TryLock(stream))
            {
                stream.Dispose();
                return null;
            }
            if (SameFile(path, stream)) return new FolderLock(folder, stream, FileKinds.Identity(folder));
            stream.Dispose();
        }
        return null;
    }

    /// <summary>Whether the folder at the path is still the one locked, with the lock file still in it.</summary>
    public bool StillInPlace()
    {
        if (!Directory.Exists(Folder)) return false;
        if (_folderIdentity is not null && FileKinds.Identity(Folder) is { } now && !now.AsSpan().SequenceEqual(_folderIdentity)) return false;
        return SameFile(Path.Combine(Folder, FileName), _stream);
    }

    /// <summary>Releases the lock and removes the lock file while it is still ours.</summary>
    public void Dispose()
    {
        try
        {
            if (StillInPlace()) File.Delete(Path.Combine(Folder, FileName));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
        }
        _stream.Dispose();
    }

    private static bool SameFile(string path, FileStream open)
    {
        if (FileKinds.Of(path) != FileKind.Regular) return false;
        var atPath = FileKinds.Identity(path);
        var held = FileKinds.Identity(open.SafeFileHandle);
        return atPath is null || held is null || atPath.AsSpan().SequenceEqual(held);
    }

    private static bool TryLock(FileStream stream)
    {
        if (OperatingSystem.IsWindows())
        {
            try
            {
                stream.Lock(0, 1);
                return true;
            }
            catch (IOException)
            {
                return false;
            }
        }
        // flock, not fcntl: an fcntl lock belongs to the process and dies when the process closes ANY handle
        // on the file, and two runs in one process would not exclude each other; flock belongs to this handle.
        try
        {
            return FLock((int)stream.SafeFileHandle.DangerousGetHandle(), LockExclusive | LockNonBlocking) == 0;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return true;
        }
    }

    // LOCK_EX and LOCK_NB of flock(2), the same values on Linux and the BSDs.
    private const int LockExclusive = 2, LockNonBlocking = 4;

    [DllImport("libc", EntryPoint = "flock", SetLastError = true)]
    private static extern int FLock(int fd, int operation);
}
