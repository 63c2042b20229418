using System.Diagnostics;
using System.Globalization;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// Removes what killed runs left: <c>NAME.PID.tmp</c> files whose process is gone, in the folder and its
/// direct subfolders, for the kinds of file a run writes (a user's "notes.2023.tmp" is not one). A live
/// process's are its writes in progress and are kept.
/// </summary>
public static class AbandonedTemporaries
{
    private static readonly string[] OutputExtensions = [".json", ".csv", ".svg", ".glb", WriteProbe.Name];

    /// <summary>Best effort: a folder that cannot be listed is left as it is, and the run's own writes say what is wrong.</summary>
    public static void Remove(string root)
    {
        string[] folders;
        // Real subfolders only: a linked one leads outside the folder, whose files are not this run's to remove.
        try { folders = Directory.EnumerateDirectories(root).Where(d => FileKinds.Of(d) == FileKind.Folder).Prepend(root).ToArray(); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { return; }
        foreach (var folder in folders)
        {
            IEnumerable<string> names;
            try { names = Directory.EnumerateFiles(folder, "*" + AtomicFile.TemporarySuffix).ToArray(); }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException) { continue; }
            foreach (var name in names)
                if (Owner(name) is { } pid && !IsAlive(pid) && FileKinds.Of(name) == FileKind.Regular)
                {
                    try { File.Delete(name); } catch (IOException) { } catch (UnauthorizedAccessException) { }
                }
        }
    }

    private static int? Owner(string path)
    {
        var stem = path[..^AtomicFile.TemporarySuffix.Length];
        var dot = stem.LastIndexOf('.');
        if (dot <= 0 || !OutputExtensions.Any(e => stem.AsSpan(0, dot).EndsWith(e, StringComparison.Ordinal))) return null;
        return int.TryParse(stem.AsSpan(dot + 1), NumberStyles.None, CultureInfo.InvariantCulture, out var pid) ? pid : null;
    }

    private static bool IsAlive(int pid)
    {
        if (pid == Environment.ProcessId) return true;
        try
        {
            using var process = Process.GetProcessById(pid);
            return !process.HasExited;
        }
        catch (Exception e) when (e is ArgumentException or InvalidOperationException)
        {
            return false;
        }
    }
}
