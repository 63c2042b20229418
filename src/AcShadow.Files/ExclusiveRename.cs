using System.Runtime.InteropServices;
using System.Text;

namespace AcShadow.Files;

/// <summary>
/// A rename that never replaces what is at its target: Linux's <c>renameat2(2)</c> with <c>RENAME_NOREPLACE</c>,
/// through libc. The kernel looks the new name up under the folder lock the rename holds anyway, so the caller
/// need not look first (each look at a name the folder does not hold yet takes that lock too, and a second
/// writer in the folder waits for it), and nothing put there meanwhile can be replaced.
/// </summary>
internal static class ExclusiveRename
{
    private const int AtFdCwd = -100;
    private const uint NoReplace = 1; // RENAME_NOREPLACE
    private const int Exists = 17, PermissionDenied = 13, NotPermitted = 1; // EEXIST, EACCES, EPERM
    private const int Invalid = 22, NoSystemCall = 38, NotSupported = 95; // EINVAL, ENOSYS, EOPNOTSUPP

    private static bool _libcHasIt = true;

    /// <summary>
    /// True: renamed; false: something is at <paramref name="target"/> and both names are as they were; null: the
    /// platform, libc or file system cannot rename so (nothing was renamed).
    /// </summary>
    public static bool? Move(string source, string target)
    {
        if (!OperatingSystem.IsLinux() || !_libcHasIt) return null;
        var from = Encoding.UTF8.GetBytes(source + "\0");
        var to = Encoding.UTF8.GetBytes(target + "\0");
        int result;
        try
        {
            result = Call(AtFdCwd, ref from[0], AtFdCwd, ref to[0], NoReplace);
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            _libcHasIt = false;
            return null;
        }
        if (result == 0) return true;
        var error = Marshal.GetLastPInvokeError();
        return error switch
        {
            Exists => false,
            // The flag is the file system's to support (EINVAL), the call the kernel's.
            Invalid or NoSystemCall or NotSupported => null,
            PermissionDenied or NotPermitted => throw new UnauthorizedAccessException($"{Marshal.GetPInvokeErrorMessage(error)}: '{target}'"),
            _ => throw new IOException($"{Marshal.GetPInvokeErrorMessage(error)}: '{target}'"),
        };
    }

    [DllImport("libc", EntryPoint = "renameat2", SetLastError = true)]
    private static extern int Call(int fromFolder, ref byte from, int toFolder, ref byte to, uint flags);
}
