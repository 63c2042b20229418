using System.Runtime.InteropServices;

namespace AcShadow.Bench.Harness;

/// <summary>The machine a run was measured on, as docs/performance.md reports it.</summary>
/// <param name="CoreLoopMs">Each core's time for one fixed loop at the start (<see cref="CoreSpeed"/>): a shared VM's cores can differ by half.</param>
public sealed record MachineInfo(int Cores, string Cpu, double RamGiB, string Os, string Dotnet, double LoadAverage, IReadOnlyList<double> CoreLoopMs)
{
    public static MachineInfo Current() => new(
        Environment.ProcessorCount,
        ProcLine("/proc/cpuinfo", "model name") ?? RuntimeInformation.ProcessArchitecture.ToString(),
        (ProcLine("/proc/meminfo", "MemTotal") is { } kb ? double.Parse(kb.Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture) : 0) / 1048576.0,
        RuntimeInformation.OSDescription,
        RuntimeInformation.FrameworkDescription,
        CurrentLoadAverage(),
        CoreSpeed.Measure());

    /// <summary>The 1-minute load average: a busy machine makes every figure noisier.</summary>
    public static double CurrentLoadAverage()
    {
        try
        {
            return double.Parse(File.ReadAllText("/proc/loadavg").Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
        }
        catch (IOException) { return double.NaN; }
        catch (UnauthorizedAccessException) { return double.NaN; }
    }

    private static string? ProcLine(string file, string key)
    {
        try
        {
            return File.ReadLines(file).Where(l => l.StartsWith(key, StringComparison.Ordinal))
                .Select(l => l[(l.IndexOf(':') + 1)..].Trim()).FirstOrDefault();
        }
        catch (IOException) { return null; }
        catch (UnauthorizedAccessException) { return null; }
    }
}
