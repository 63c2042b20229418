using System.Buffers.Binary;
using System.Runtime.InteropServices;
using System.Text;
using Microsoft.Win32.SafeHandles;

namespace AcShadow.Files;

/// <summary>
/// Tells a regular file from a device, a FIFO, a socket or a link before anything opens it: opening a FIFO
/// waits for a writer, and replacing a device by rename replaces the device. .NET's file API does not say
/// what kind of file a path names, so on Linux this asks the kernel through libc's <c>statx(2)</c>, whose
/// <c>struct statx</c> has one documented layout on every architecture (linux/stat.h). Where libc has no
/// statx (macOS, an old libc) the kinds .NET can tell are told and the rest are <see cref="FileKind.Unknown"/>.
/// </summary>
public static class FileKinds
{
    /// <summary>What <paramref name="path"/> names; with <paramref name="followLinks"/>, what a final symbolic link points at.</summary>
    public static FileKind Of(string path, bool followLinks = false)
    {
        if (OperatingSystem.IsWindows()) return OfDotNet(path, followLinks);
        var status = new byte[Statx.Size];
        if (Statx.OfPath(path, followLinks, status) is not { } found) return OfDotNet(path, followLinks);
        return found ? KindOf(status) : FileKind.Missing;
    }

    /// <summary>
    /// What <paramref name="path"/> names (a final link not followed) and its device and inode numbers, in one
    /// look where <see cref="Of"/> and <see cref="Identity(string)"/> take two: for a run that surveys thousands of
    /// paths. The identity is the link's own for a link, and null when the path names nothing or the platform cannot say.
    /// </summary>
    public static (FileKind Kind, byte[]? Identity) Look(string path)
    {
        if (OperatingSystem.IsWindows()) return (OfDotNet(path, followLinks: false), null);
        var status = new byte[Statx.Size];
        return Statx.OfPath(path, followLinks: false, status) switch
        {
            null => (OfDotNet(path, followLinks: false), null),
            false => (FileKind.Missing, null),
            true => (KindOf(status), IdentityOf(status)),
        };
    }

    private static FileKind KindOf(byte[] status) =>
        (BinaryPrimitives.ReadUInt16LittleEndian(status.AsSpan(Statx.ModeOffset)) & TypeMask) switch
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

    /// <summary>
    /// The device and inode numbers of what <paramref name="path"/> names (a final link followed): they
    /// differ between two files and not between two looks at one file. Null when the path names nothing or
    /// the platform cannot say.
    /// </summary>
    public static byte[]? Identity(string path)
    {
        if (OperatingSystem.IsWindows()) return null;
        var status = new byte[Statx.Size];
        return Statx.OfPath(path, followLinks: true, status) == true ? IdentityOf(status) : null;
    }

    /// <summary>As <see cref="Identity(string)"/>, for an open file.</summary>
    public static byte[]? Identity(SafeFileHandle handle)
    {
        if (OperatingSystem.IsWindows()) return null;
        var status = new byte[Statx.Size];
        return Statx.OfHandle(handle, status) ? IdentityOf(status) : null;
    }

    private const int TypeMask = 0xF000;

    private static byte[] IdentityOf(byte[] status) =>
        [.. status.AsSpan(Statx.InodeOffset, 8), .. status.AsSpan(Statx.DeviceOffset, 8)];

    /// <summary>What .NET's own API can tell: links, folders and files (a device, FIFO or socket is "a file" to it).</summary>
    private static FileKind OfDotNet(string path, bool followLinks)
    {
        FileSystemInfo info = Directory.Exists(path) ? new DirectoryInfo(path) : new FileInfo(path);
        if (info.LinkTarget is not null)
        {
            if (!followLinks) return FileKind.SymbolicLink;
            var target = info.ResolveLinkTarget(returnFinalTarget: true);
            return target is null || !target.Exists ? FileKind.Missing : target is DirectoryInfo ? FileKind.Folder : KindOfFile(target);
        }
        if (!info.Exists) return FileKind.Missing;
        return info is DirectoryInfo ? FileKind.Folder : KindOfFile(info);
    }

    // Only Windows tells a regular file apart in its attributes; elsewhere this fallback cannot.
    private static FileKind KindOfFile(FileSystemInfo info) => OperatingSystem.IsWindows() ? FileKind.Regular : FileKind.Unknown;

    /// <summary>
    /// statx(2) through libc. Offsets are those of <c>struct statx</c> in linux/stat.h, the same on every
    /// architecture: stx_mode (u16) at 28, stx_ino (u64) at 32, stx_dev_major and stx_dev_minor (u32) at 136.
    /// </summary>
    private static class Statx
    {
        public const int Size = 256;
        public const int ModeOffset = 28, InodeOffset = 32, DeviceOffset = 136;

        private const int AtFdCwd = -100;
        private const int AtSymlinkNoFollow = 0x100, AtEmptyPath = 0x1000;
        private const uint TypeAndInode = 0x1 | 0x100; // STATX_TYPE | STATX_INO; the device numbers always come

        /// <summary>True: found and filled; false: nothing there (or not reachable); null: this libc has no statx.</summary>
        public static bool? OfPath(string path, bool followLinks, byte[] status)
        {
            var name = Encoding.UTF8.GetBytes(path + "\0");
            try
            {
                return Call(AtFdCwd, ref name[0], followLinks ? 0 : AtSymlinkNoFollow, TypeAndInode, ref status[0]) == 0;
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                return null;
            }
        }

        /// <summary>An open file's status: the empty path names the descriptor itself (AT_EMPTY_PATH).</summary>
        public static bool OfHandle(SafeFileHandle handle, byte[] status)
        {
            var empty = new byte[1];
            var added = false;
            try
            {
                handle.DangerousAddRef(ref added);
                return Call((int)handle.DangerousGetHandle(), ref empty[0], AtEmptyPath, TypeAndInode, ref status[0]) == 0;
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                return false;
            }
            finally
            {
                if (added) handle.DangerousRelease();
            }
        }

        [DllImport("libc", EntryPoint = "statx", SetLastError = true)]
        private static extern int Call(int dirFd, ref byte path, int flags, uint mask, ref byte status);
    }
}
