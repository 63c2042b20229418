using System.Globalization;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// The open-file limit (ulimit -n), checked before anything else runs. The runtime keeps a descriptor open
/// for every assembly it loads, and threads and output files need more; under about a hundred a run fails
/// somewhere different on every machine — an assembly that cannot load, a worker thread that cannot start,
/// or a runtime that stops itself with a stack trace of its own. One line up front says it plainly instead.
/// </summary>
public static class DescriptorLimit
{
    /// <summary>Enough for every command at any --jobs on the machines measured (a batch of the sample needs about 70).</summary>
    public const long Minimum = 128;

    /// <summary>The soft limit from /proc/self/limits; null where there is none (not Linux) or it cannot be read.</summary>
    public static long? Soft()
    {
        try
        {
            if (!OperatingSystem.IsLinux()) return null;
            foreach (var line in File.ReadLines("/proc/self/limits"))
            {
                if (!line.StartsWith("Max open files", StringComparison.Ordinal)) continue;
                var fields = line["Max open files".Length..].Split(' ', StringSplitOptions.RemoveEmptyEntries);
                return fields.Length > 0 && long.TryParse(fields[0], NumberStyles.None, CultureInfo.InvariantCulture, out var soft) ? soft : null;
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
        }
        return null;
    }

    /// <summary>The error line when the limit is too low to run; null when it is enough (or unknown).</summary>
    public static string? Problem() => Soft() is { } soft && soft < Minimum
        ? $"acshadow: the open-file limit (ulimit -n) is {soft}, too few to run: acshadow needs at least {Minimum} (raise it, e.g. `ulimit -n 1024`)"
        : null;
}
