using AcShadow.Cli.Infrastructure;
using AcShadow.Files;
using AcShadow.Fixtures.Formats;

namespace AcShadow.Cli.Output;

/// <summary>Where a file of a run lands: its relative path (always '/'-separated) under the output folder, and never beyond it.</summary>
public static class OutputPaths
{
    /// <summary>The folders batch, dump and scene write in (setups/, gfxobjs/, cells/, movement/), as the file formats place their files.</summary>
    public static IReadOnlyList<string> Subfolders { get; } =
        [.. FileFormats.All.Select(f => f.PathPattern).Where(p => p.Contains('/')).Select(p => p[..p.IndexOf('/')]).Distinct()];

    /// <summary>
    /// The full path of <paramref name="relativePath"/> under <paramref name="root"/>. A path that would
    /// leave the folder — by its spelling, or on disk through a symbolic link (or a file) where one of its
    /// folders belongs — is refused (exit 6): acshadow writes only inside --out, and the folder lock covers
    /// only what is inside.
    /// </summary>
    public static string Target(string root, string relativePath)
    {
        RequireSpelledInside(root, relativePath);
        RequireFoldersInside(root, relativePath);
        return FullPath(root, relativePath);
    }

    /// <summary>
    /// <see cref="Target"/> of each path, each folder on the way looked at once, not once for every path in it:
    /// a batch surveys every path it plans, thousands in setups/ and gfxobjs/.
    /// </summary>
    public static string[] Targets(string root, IReadOnlyList<string> relativePaths)
    {
        var foldersSeen = new HashSet<string>(StringComparer.Ordinal);
        var targets = new string[relativePaths.Count];
        for (var i = 0; i < targets.Length; i++)
        {
            var relative = relativePaths[i];
            RequireSpelledInside(root, relative);
            if (foldersSeen.Add(relative[..Math.Max(0, relative.LastIndexOf('/'))])) RequireFoldersInside(root, relative);
            targets[i] = FullPath(root, relative);
        }
        return targets;
    }

    // By spelling: the paths a run makes are plain names under the folder (a report's own name may hold
    // any character a file name may, ':' included); none is rooted or climbs out.
    private static void RequireSpelledInside(string root, string relativePath)
    {
        if (Path.IsPathRooted(relativePath) || relativePath.Split('/', Path.DirectorySeparatorChar).Contains(".."))
            throw new CliException(ExitCodes.OutputFailed, $"--out: {relativePath} is not a path inside {root}: acshadow writes only inside --out");
    }

    private static void RequireFoldersInside(string root, string relativePath)
    {
        if (FolderLinks.FirstDetour(root, relativePath) is { } detour)
            throw new CliException(ExitCodes.OutputFailed, Detour(detour.Path, detour.Kind));
    }

    private static string FullPath(string root, string relativePath) =>
        Path.GetFullPath(Path.Combine(root, relativePath.Replace('/', Path.DirectorySeparatorChar)));

    /// <summary>Before anything is written: none of the folders a run writes in is a link (or a file) leading elsewhere.</summary>
    public static void RequireSubfoldersInside(string root)
    {
        foreach (var sub in Subfolders)
        {
            var path = Path.Combine(root, sub);
            if (FileKinds.Of(path) is var kind && kind is not (FileKind.Missing or FileKind.Folder or FileKind.Unknown))
                throw new CliException(ExitCodes.OutputFailed, Detour(path, kind) + "; nothing was written");
        }
    }

    private static string Detour(string path, FileKind kind) => kind == FileKind.SymbolicLink
        ? $"--out: {path} is a symbolic link (to {FolderLinks.TargetOf(path)}), where acshadow writes a folder: acshadow writes only inside --out, never through a link (the folder lock does not cover where it leads): replace the link with a folder or pass another folder"
        : $"--out: {path} is {FileKinds.Describe(kind)}, where acshadow writes a folder: move it away or pass another folder";

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
