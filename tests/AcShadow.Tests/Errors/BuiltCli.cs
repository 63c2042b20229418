using System.Diagnostics;
using AcShadow.Cli;

namespace AcShadow.Tests.Errors;

/// <summary>
/// Runs the built acshadow as a real process, for what only a process shows: another user's permissions,
/// a file-size limit or a full file system, being killed part-way.
/// </summary>
public static class BuiltCli
{
    public static string Dll => typeof(AcShadowApp).Assembly.Location;

    public static bool IsRoot => Environment.UserName == "root";

    public static ProcessStartInfo Start(IEnumerable<string> prefix, params string[] args)
    {
        var all = prefix.Concat(["dotnet", Dll]).Concat(args).ToArray();
        var info = new ProcessStartInfo(all[0]) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in all[1..]) info.ArgumentList.Add(a);
        // The runtime's W^X double mapping creates a file of its own, which a file-size limit would stop.
        info.Environment["DOTNET_EnableWriteXorExecute"] = "0";
        return info;
    }

    public static (int ExitCode, string Out, string Error) Run(IEnumerable<string> prefix, params string[] args) =>
        Wait(Start(prefix, args), "acshadow " + string.Join(' ', args));

    private static (int ExitCode, string Out, string Error) Wait(ProcessStartInfo info, string what)
    {
        using var process = Process.Start(info)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(2)))
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"{what} did not finish in 2 minutes");
        }
        return (process.ExitCode, output.Result, error.Result);
    }

    /// <summary>Runs a bash script (after <paramref name="prefix"/>), for limits and mounts that must wrap acshadow.</summary>
    public static (int ExitCode, string Out, string Error) RunShell(IEnumerable<string> prefix, string script)
    {
        var all = prefix.Concat(["bash", "-c", script]).ToArray();
        var info = new ProcessStartInfo(all[0]) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in all[1..]) info.ArgumentList.Add(a);
        info.Environment["DOTNET_EnableWriteXorExecute"] = "0";
        return Wait(info, script);
    }

    /// <summary>
    /// The prefix that runs acshadow as an ordinary user, so file permissions apply: root reads and writes
    /// through any mode bits, so as root the process drops to nobody (setpriv, util-linux).
    /// </summary>
    public static string[] AsUnprivilegedUser()
    {
        if (!IsRoot) return [];
        Assert.True(File.Exists("/usr/bin/setpriv") || File.Exists("/bin/setpriv"),
            "these tests run as root, where chmod 000 does not stop a read; they need setpriv (util-linux) to drop to nobody");
        return ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"];
    }

    /// <summary>Lets another user traverse and read a folder (temporary folders are created 0700).</summary>
    public static void OpenToEveryone(string folder) =>
        SetMode(folder, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute
            | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute);

    public static void SetMode(string path, UnixFileMode mode)
    {
        if (OperatingSystem.IsWindows()) throw new PlatformNotSupportedException("these tests need Unix file modes");
        File.SetUnixFileMode(path, mode);
    }
}
