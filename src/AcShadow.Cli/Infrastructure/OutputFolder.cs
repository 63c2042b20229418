using AcShadow.Core.Export;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Writes export files under a folder atomically: each file goes to a temporary name beside its target
/// and is renamed over it, so an interrupted run never leaves a truncated file.
/// </summary>
public static class OutputFolder
{
    public static long WriteAtomically(string root, OutputFile file) => WriteAtomically(root, file.RelativePath, file.Content);

    public static long WriteAtomically(string root, string relativePath, byte[] content)
    {
        var target = Path.GetFullPath(Path.Combine(root, relativePath.Replace('/', Path.DirectorySeparatorChar)));
        var temp = target + $".{Environment.ProcessId}.tmp";
        try
        {
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.WriteAllBytes(temp, content);
            File.Move(temp, target, overwrite: true);
            return content.LongLength;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            TryDelete(temp);
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {target}: {e.Message} (check --out points at a writable folder)");
        }
    }

    /// <summary>True when the file already holds exactly these bytes (for --incremental).</summary>
    public static bool IsUnchanged(string root, string relativePath, byte[] content)
    {
        var target = Path.Combine(root, relativePath.Replace('/', Path.DirectorySeparatorChar));
        if (!File.Exists(target)) return false;
        var info = new FileInfo(target);
        if (info.Length != content.LongLength) return false;
        return File.ReadAllBytes(target).AsSpan().SequenceEqual(content);
    }

    private static void TryDelete(string path)
    {
        try { if (File.Exists(path)) File.Delete(path); } catch (IOException) { } catch (UnauthorizedAccessException) { }
    }
}
