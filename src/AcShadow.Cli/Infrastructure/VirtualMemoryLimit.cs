using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// A virtual-memory limit (`ulimit -v`, RLIMIT_AS). The runtime's defaults assume address space is free: the
/// GC reserves a range for its heap sized from the limit, and W^X maps every page of compiled code twice, so
/// under 1-2 GB the process used to abort (exit 134, "Failed to create RW mapping", "No usable version of
/// libssl") before acshadow could say anything. Under a limit acshadow runs itself once more as a child with
/// W^X off and the GC's range at what the limit leaves after <see cref="RuntimeShare"/>; what then runs out is an
/// OutOfMemoryException, reported as one line (exit 1). The settings are environment-only (DOTNET_*), read
/// when the runtime starts, hence the child.
/// </summary>
public static class VirtualMemoryLimit
{
    /// <summary>Set in the child, so it does not relaunch again.</summary>
    public const string ChildVariable = "ACSHADOW_MEMORY_LIMITED";

    /// <summary>
    /// Address space the runtime itself takes besides the heap (code, thread stacks, mapped assemblies and
    /// libraries): measured at about 900 MiB on Linux x64 with .NET 10, so acshadow needs a limit above 1 GB.
    /// </summary>
    public const ulong RuntimeShare = 960UL << 20;

    private const int RlimitAs = 9; // Linux

    [StructLayout(LayoutKind.Sequential)]
    private struct Rlimit
    {
        public ulong Current;
        public ulong Maximum;
    }

    [DllImport("libc", EntryPoint = "getrlimit", SetLastError = true)]
    private static extern int GetRlimit(int resource, out Rlimit limit);

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    private static extern int Kill(int pid, int signal);

    /// <summary>The limit in bytes, or null when there is none (or it cannot be asked).</summary>
    public static ulong? Bytes()
    {
        if (!OperatingSystem.IsLinux()) return null;
        try
        {
            return GetRlimit(RlimitAs, out var limit) == 0 && limit.Current != ulong.MaxValue ? limit.Current : null;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return null;
        }
    }

    /// <summary>"ulimit -v 2000000 (1953 MiB)", for the out-of-memory line; null without a limit.</summary>
    public static string? Describe() => Bytes() is { } bytes
        ? string.Create(CultureInfo.InvariantCulture, $"the virtual-memory limit is {bytes >> 20} MiB (ulimit -v {bytes >> 10})")
        : null;

    /// <summary>
    /// Under a limit, runs acshadow again as a child with settings that fit in it, and gives the child's exit
    /// code; null when this process should run the command itself.
    /// </summary>
    public static int? RunLimitedChild(string[] args)
    {
        if (Environment.GetEnvironmentVariable(ChildVariable) is not null || Bytes() is not { } limit) return null;
        var host = Environment.ProcessPath;
        if (host is null) return null;
        var info = new ProcessStartInfo(host) { UseShellExecute = false };
        // Run as `dotnet acshadow.dll`, the host needs the assembly again; an apphost (the installed tool) does not.
        if (Path.GetFileNameWithoutExtension(host) == "dotnet") info.ArgumentList.Add(Environment.GetCommandLineArgs()[0]);
        foreach (var a in args) info.ArgumentList.Add(a);
        var heap = Math.Max(64UL << 20, limit > RuntimeShare ? (limit - RuntimeShare) / 2 : 0) & ~((1UL << 20) - 1);
        info.Environment[ChildVariable] = "1";
        info.Environment["DOTNET_EnableWriteXorExecute"] = "0";
        info.Environment["DOTNET_GCRegionRange"] = heap.ToString("X", CultureInfo.InvariantCulture);
        Process child;
        try
        {
            child = Process.Start(info)!;
        }
        catch (Exception e) when (e is System.ComponentModel.Win32Exception or OutOfMemoryException)
        {
            return null;
        }
        using (child)
        {
            // A terminal's Ctrl-C reaches the child too (same process group), which reports it; SIGTERM sent
            // to this process alone is passed on. Either way the child's exit code is the answer.
            using var interrupt = PosixSignalRegistration.Create(PosixSignal.SIGINT, c => c.Cancel = true);
            using var terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM, c =>
            {
                c.Cancel = true;
                Kill(child.Id, 15);
            });
            child.WaitForExit();
            return child.ExitCode;
        }
    }
}
