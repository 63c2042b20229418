using System.Diagnostics;
using System.Globalization;

namespace AcShadow.Bench.Harness;

/// <summary>
/// Runs a command as a whole process and measures its wall time, peak resident memory and CPU time:
/// through /usr/bin/time -f "%M %U %S" when the machine has it, else by polling /proc/PID/status VmHWM (which can miss
/// a peak reached in the last few milliseconds).
/// </summary>
public static class ProcessRunner
{
    private const string GnuTime = "/usr/bin/time";

    /// <summary>Wall seconds, peak resident MiB, and CPU seconds (user + system; NaN without /usr/bin/time).</summary>
    public sealed record Outcome(double Seconds, double PeakMiB, double CpuSeconds, string Stdout, string Stderr);

    /// <summary>A .dll is run with the dotnet host, anything else directly.</summary>
    public static (string File, string[] Prefix) Command(string path) =>
        path.EndsWith(".dll", StringComparison.OrdinalIgnoreCase) ? (DotnetHost(), [path]) : (path, []);

    public static Outcome Run(string path, IReadOnlyList<string> args)
    {
        var (file, prefix) = Command(path);
        var useTime = File.Exists(GnuTime) && OperatingSystem.IsLinux();
        var memoryFile = useTime ? Path.GetTempFileName() : null;
        var info = new ProcessStartInfo(useTime ? GnuTime : file)
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        if (useTime) foreach (var a in new[] { "-f", "%M %U %S", "-o", memoryFile!, file }) info.ArgumentList.Add(a);
        foreach (var a in prefix.Concat(args)) info.ArgumentList.Add(a);
        info.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";

        var clock = Stopwatch.StartNew();
        using var process = Process.Start(info) ?? throw new InvalidOperationException($"cannot start {file}");
        var stdout = process.StandardOutput.ReadToEndAsync();
        var stderr = process.StandardError.ReadToEndAsync();
        long polledKb = 0;
        if (!useTime)
            while (!process.WaitForExit(10)) polledKb = Math.Max(polledKb, VmHwmKb(process.Id));
        process.WaitForExit();
        var seconds = clock.Elapsed.TotalSeconds;
        if (process.ExitCode != 0)
            throw new InvalidOperationException($"{file} {string.Join(' ', prefix.Concat(args))} exited {process.ExitCode}: {stderr.Result.Trim()}");
        double peakMiB, cpu = double.NaN;
        if (useTime)
        {
            var fields = File.ReadAllText(memoryFile!).Trim().Split('\n')[^1].Split(' ');
            File.Delete(memoryFile!);
            peakMiB = long.Parse(fields[0], CultureInfo.InvariantCulture) / 1024.0;
            cpu = double.Parse(fields[1], CultureInfo.InvariantCulture) + double.Parse(fields[2], CultureInfo.InvariantCulture);
        }
        else peakMiB = polledKb / 1024.0;
        return new Outcome(seconds, peakMiB, cpu, stdout.Result, stderr.Result);
    }

    private static long VmHwmKb(int pid)
    {
        try
        {
            foreach (var line in File.ReadLines($"/proc/{pid}/status"))
                if (line.StartsWith("VmHWM:", StringComparison.Ordinal))
                    return long.Parse(line[6..].Trim().Split(' ')[0], CultureInfo.InvariantCulture);
        }
        catch (IOException) { }
        catch (UnauthorizedAccessException) { }
        return 0;
    }

    private static string DotnetHost() =>
        Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host ? host
        : Environment.ProcessPath is { } p && Path.GetFileNameWithoutExtension(p) == "dotnet" ? p
        : "dotnet";
}
