using System.Runtime.InteropServices;
using System.Text;

namespace AcShadow.Files;

/// <summary>
/// Tells a regular file from a device, a FIFO, a socket or a link before anything opens it: opening a FIFO
/// waits for a writer, and replacing a device by rename replaces the device. .NET's file API does not say
/// what kind of file a path names, so on Unix this asks the runtime's own native layer (the stat the BCL
/// itself uses, whose mode carries the POSIX file type bits).
/// </summary>
public static class FileKinds
{
    /// <summary>What <paramref name="path"/> names; with <paramref name="followLinks"/>, what a final symbolic link points at.</summary>
    public static FileKind Of(string path, bool followLinks = false)
    {
        if (OperatingSystem.IsWindows()) return OfWindows(path, followLinks);
        var status = new byte[StatusBytes];
        var name = Encoding.UTF8.GetBytes(path + "\0");
        int result;
        try
        {
            result = followLinks ? Stat(ref name[0], ref status[0]) : LStat(ref name[0], ref status[0]);
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return File.Exists(path) ? FileKind.Unknown : Directory.Exists(path) ? FileKind.Folder : FileKind.Missing;
        }
        if (result != 0) return FileKind.Missing;
        return (BitConverter.ToInt32(status, ModeOffset) & TypeMask) switch
        {
            0x8000 => FileKind.Regular,
            0x4000 => FileKind.Folder,
            0xA000 => FileKind.SymbolicLink,
            0x1000 => FileKind.Fifo,
            0x2000 => FileKind.CharacterDevice,
            0x6000 => FileKind.BlockDevice,
            0xC000 => FileKind.Socket,
            _ => FileKind.Unknown,
        };
    }

    /// <summary>"a FIFO", "a character device", …: for messages.</summary>
    public static string Describe(FileKind kind) => kind switch
    {
        FileKind.Regular => "a regular file",
        FileKind.Folder => "a folder",
        FileKind.SymbolicLink => "a symbolic link",
        FileKind.Fifo => "a FIFO (named pipe)",
        FileKind.CharacterDevice => "a character device",
        FileKind.BlockDevice => "a block device",
        FileKind.Socket => "a socket",
        FileKind.Missing => "missing",
        _ => "a special file",
    };

    private static FileKind OfWindows(string path, bool followLinks)
    {
        FileSystemInfo info = Directory.Exists(path) ? new DirectoryInfo(path) : new FileInfo(path);
        if (!info.Exists) return FileKind.Missing;
        if (info.LinkTarget is not null)
        {
            if (!followLinks) return FileKind.SymbolicLink;
            var target = info.ResolveLinkTarget(returnFinalTarget: true);
            return target is null || !target.Exists ? FileKind.Missing : target is DirectoryInfo ? FileKind.Folder : FileKind.Regular;
        }
        return info is DirectoryInfo ? FileKind.Folder : FileKind.Regular;
    }

    // The runtime's FileStatus: int32 Flags, int32 Mode (S_IFMT bits as POSIX spells them), then sizes and
    // times; a generous buffer covers every version's tail.
    private const int StatusBytes = 256;
    private const int ModeOffset = 4;
    private const int TypeMask = 0xF000;

    /// <summary>
    /// Bytes that differ between two files and not between two looks at one file: the device and inode
    /// numbers (and the fields beside them that do not change); null when the path names nothing or the
    /// platform cannot say.
    /// </summary>
    public static byte[]? Identity(string path)
    {
        if (OperatingSystem.IsWindows()) return null;
        var status = new byte[StatusBytes];
        var name = Encoding.UTF8.GetBytes(path + "\0");
        try
        {
            return Stat(ref name[0], ref status[0]) == 0 ? status[IdentityStart..IdentityEnd] : null;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return null;
        }
    }

    /// <summary>As <see cref="Identity(string)"/>, for an open file.</summary>
    public static byte[]? Identity(Microsoft.Win32.SafeHandles.SafeFileHandle handle)
    {
        if (OperatingSystem.IsWindows()) return null;
        var status = new byte[StatusBytes];
        try
        {
            return FStat(handle.DangerousGetHandle(), ref status[0]) == 0 ? status[IdentityStart..IdentityEnd] : null;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return null;
        }
    }

    // After the mode, owner, size and eight time fields (88 bytes) come the device, the inode (with the
    // device a special file stands for between them in newer runtimes) and user flags: times are left out,
    // since reading a file changes its access time.
    private const int IdentityStart = 88, IdentityEnd = 120;

    [DllImport("libSystem.Native", EntryPoint = "SystemNative_FStat", SetLastError = true)]
    private static extern int FStat(nint fd, ref byte status);

    [DllImport("libSystem.Native", EntryPoint = "SystemNative_LStat", SetLastError = true)]
    private static extern int LStat(ref byte path, ref byte status);

    [DllImport("libSystem.Native", EntryPoint = "SystemNative_Stat", SetLastError = true)]
    private static extern int Stat(ref byte path, ref byte status);
}
