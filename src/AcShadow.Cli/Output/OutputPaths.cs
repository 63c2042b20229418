using AcShadow.Cli.Infrastructure;

namespace AcShadow.Cli.Output;

/// <summary>Where a file of a run lands: its relative path (always '/'-separated) under the output folder.</summary>
public static class OutputPaths
{
    public static string Target(string root, string relativePath) =>
        Path.GetFullPath(Path.Combine(root, relativePath.Replace('/', Path.DirectorySeparatorChar)));

    /// <summary>An empty --out is a usage mistake (an unquoted empty variable), not a path to resolve.</summary>
    public static void RequireNamed(string path, string option = "--out") =>
        RequireNamed(path, option, "a folder", "fixtures");

    /// <summary>As above, saying what the option takes: "a folder" (e.g. fixtures) or "a file name" (e.g. doctor.json).</summary>
    public static void RequireNamed(string path, string option, string what, string example)
    {
        if (string.IsNullOrWhiteSpace(path))
            throw new CliException(ExitCodes.Usage, $"{option}: the path is empty: pass {what} (e.g. {option} {example})");
    }
}
