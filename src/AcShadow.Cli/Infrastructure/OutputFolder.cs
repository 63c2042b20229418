using System.Buffers;
using System.Diagnostics;
using System.Globalization;
using Microsoft.Win32.SafeHandles;
using AcShadow.Core.Batch;
using AcShadow.Core.Export;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Writes export files under a folder atomically: each file goes to a temporary name beside its target
/// (<c>NAME.PID.tmp</c>) and is renamed over it, so an interrupted run never leaves a truncated file.
/// A killed run's temporary files are removed by the next run into the same folder.
/// </summary>
public static class OutputFolder
{
    private const string TempSuffix = ".tmp";

    /// <summary>
    /// Before any work is written: the folder exists or is created, a file can be created in it, and the
    /// temporary files of runs no longer alive are removed (from it and its direct subfolders).
    /// </summary>
    public static void Prepare(string root, string option = "--out")
    {
        if (File.Exists(root))
            throw new CliException(ExitCodes.OutputFailed, $"{option}: {root} is a file: pass a folder (it is created when missing)");
        try
        {
            Directory.CreateDirectory(root);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"{option}: cannot create folder {root}: {e.Message} (pass a folder you can write to)");
        }
        var probe = Path.Combine(root, $"{WriteTestName}.{Environment.ProcessId}{TempSuffix}");
        try
        {
            File.WriteAllBytes(probe, [0]);
            File.Delete(probe);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            TryDelete(probe);
            throw new CliException(ExitCodes.OutputFailed, $"{option}: cannot write in folder {root}: {e.Message} (pass a folder you can write to)");
        }
        RemoveAbandonedTemporaries(root);
    }

    /// <summary>
    /// Refuses, before anything is written, to replace a file acshadow does not recognise as its own
    /// (<see cref="OutputOwnership"/>) and that <paramref name="listedAsOurs"/> (the folder's own index.json)
    /// does not list, naming it; a folder where a file belongs is refused the same way.
    /// </summary>
    public static void RefuseForeignFiles(string root, IEnumerable<(string RelativePath, ReadOnlyMemory<byte> Content)> files,
        IReadOnlySet<string>? listedAsOurs = null, string option = "--out")
    {
        var foreign = new List<string>();
        foreach (var (relative, content) in files)
        {
            var target = TargetPath(root, relative);
            if (Directory.Exists(target)) foreign.Add($"{target} (a folder)");
            else if (File.Exists(target) && listedAsOurs?.Contains(relative) != true && !OutputOwnership.IsOurs(ReadHead(target), content.Span))
                foreign.Add(target);
        }
        if (foreign.Count == 0) return;
        throw new CliException(ExitCodes.OutputFailed,
            $"{option}: {foreign[0]}{(foreign.Count > 1 ? $" and {foreign.Count - 1} more" : "")} would be replaced but {(foreign.Count > 1 ? "are" : "is")} not acshadow output: " +
            "move it away or pass another folder; nothing was written");
    }

    /// <summary>
    /// The paths an acshadow index.json in the folder lists (a damaged fixture it lists is still ours to
    /// repair); empty when there is none or it is not an acshadow index.
    /// </summary>
    public static IReadOnlySet<string> ListedByIndex(string root)
    {
        var path = Path.Combine(root, BatchResult.IndexPath);
        try
        {
            if (!File.Exists(path)) return new HashSet<string>();
            return BatchIndexReader.Read(File.ReadAllBytes(path)).Files.Select(f => f.Path).ToHashSet(StringComparer.Ordinal);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or FormatException or InvalidOperationException)
        {
            return new HashSet<string>();
        }
    }

    public static long WriteAtomically(string root, OutputFile file) => WriteAtomically(root, file.RelativePath, file.Content);

    public static long WriteAtomically(string root, string relativePath, ReadOnlyMemory<byte> content) =>
        // A handle and one positional write: no stream buffer, seek or truncate of a file just created (a
        // batch writes tens of thousands; each saved call counts). Not File.WriteAllBytes: it preallocates
        // the length first, and a file the file system cannot hold then fails as an ArgumentException
        // instead of the write's own I/O error.
        Replace(root, relativePath, handle =>
        {
            RandomAccess.Write(handle, content.Span, 0);
            return content.Length;
        });

    /// <summary>As <see cref="WriteAtomically(string, string, ReadOnlyMemory{byte})"/>, for content <paramref name="write"/> streams (it writes in large chunks).</summary>
    public static long WriteAtomically(string root, string relativePath, Action<Stream> write) =>
        Replace(root, relativePath, handle =>
        {
            using var stream = new FileStream(handle, FileAccess.Write, bufferSize: 0);
            write(stream);
            return stream.Position;
        });

    /// <summary>Writes a new temporary file beside the target with <paramref name="write"/> (its length out), then renames it over the target.</summary>
    private static long Replace(string root, string relativePath, Func<SafeFileHandle, long> write)
    {
        var target = TargetPath(root, relativePath);
        var temp = target + $".{Environment.ProcessId}{TempSuffix}";
        try
        {
            long length;
            using (var handle = CreateTemporary(temp))
                length = write(handle);
            File.Move(temp, target, overwrite: true);
            return length;
        }
        // .NET reports a write past the file-size limit (EFBIG) as ArgumentOutOfRangeException, a full disk as IOException.
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentOutOfRangeException)
        {
            TryDelete(temp);
            throw new CliException(ExitCodes.OutputFailed, $"cannot write {target}: {e.Message} (check --out points at a writable folder with free space)");
        }
    }

    /// <summary>
    /// The temporary file, created new (nothing to truncate); its folder is made only when missing (a batch
    /// writes thousands of files into the same two). One left by an earlier process that had this process's
    /// id (so it was not cleared as abandoned) is replaced.
    /// </summary>
    private static SafeFileHandle CreateTemporary(string temp)
    {
        try
        {
            return File.OpenHandle(temp, FileMode.CreateNew, FileAccess.Write, FileShare.Read);
        }
        // ENOENT: the folder is missing. .NET names it a missing file instead when another thread created
        // the folder between the failed open and the error's mapping, so both mean "make the folder".
        catch (IOException e) when (e is DirectoryNotFoundException or FileNotFoundException)
        {
            Directory.CreateDirectory(Path.GetDirectoryName(temp)!);
        }
        catch (IOException) when (File.Exists(temp))
        {
            File.Delete(temp);
        }
        return File.OpenHandle(temp, FileMode.CreateNew, FileAccess.Write, FileShare.Read);
    }

    /// <summary>True when the file already holds exactly these bytes (for --incremental).</summary>
    /// <remarks>One open and chunked reads into a pooled buffer: a batch asks this of every file it makes.</remarks>
    public static bool IsUnchanged(string root, string relativePath, ReadOnlySpan<byte> content)
    {
        SafeFileHandle handle;
        try
        {
            handle = File.OpenHandle(TargetPath(root, relativePath), FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
        }
        // Missing, a folder, unreadable: not these bytes; the write that follows reports what is wrong.
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
        using (handle)
        {
            if (RandomAccess.GetLength(handle) != content.Length) return false;
            var chunk = ArrayPool<byte>.Shared.Rent(Math.Min(content.Length, 1 << 16));
            try
            {
                for (var offset = 0; offset < content.Length;)
                {
                    var read = RandomAccess.Read(handle, chunk.AsSpan(0, Math.Min(chunk.Length, content.Length - offset)), offset);
                    if (read <= 0 || !chunk.AsSpan(0, read).SequenceEqual(content.Slice(offset, read))) return false;
                    offset += read;
                }
                return true;
            }
            finally
            {
                ArrayPool<byte>.Shared.Return(chunk);
            }
        }
    }

    private static string TargetPath(string root, string relativePath) =>
        Path.GetFullPath(Path.Combine(root, relativePath.Replace('/', Path.DirectorySeparatorChar)));

    /// <summary>The kinds of file a run writes into a folder (and its write test): a user's "notes.2023.tmp" is not one.</summary>
    private static readonly string[] OutputExtensions = [".json", ".csv", ".svg", ".glb", WriteTestName];

    private const string WriteTestName = ".acshadow-write-test";

    private static int? TemporaryOwner(string path)
    {
        if (!path.EndsWith(TempSuffix, StringComparison.Ordinal)) return null;
        var stem = path[..^TempSuffix.Length];
        var dot = stem.LastIndexOf('.');
        if (dot <= 0 || !OutputExtensions.Any(e => stem.AsSpan(0, dot).EndsWith(e, StringComparison.Ordinal))) return null;
        return int.TryParse(stem.AsSpan(dot + 1), NumberStyles.None, CultureInfo.InvariantCulture, out var pid) ? pid : null;
    }

    /// <summary>A temporary file whose process is gone was left by a killed run; a live process's is its write in progress.</summary>
    private static void RemoveAbandonedTemporaries(string root)
    {
        var folders = Directory.EnumerateDirectories(root).Prepend(root);
        foreach (var folder in folders)
        {
            IEnumerable<string> names;
            try { names = Directory.EnumerateFiles(folder, "*" + TempSuffix).ToArray(); }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException) { continue; }
            foreach (var name in names)
                if (TemporaryOwner(name) is { } pid && !IsAlive(pid)) TryDelete(name);
        }
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

    private static byte[] ReadHead(string path)
    {
        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite);
            var head = new byte[OutputOwnership.HeadBytes];
            var read = stream.ReadAtLeast(head, head.Length, throwOnEndOfStream: false);
            return head[..read];
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException(ExitCodes.OutputFailed, $"cannot read {path} to check it is acshadow output: {e.Message}");
        }
    }

    private static void TryDelete(string path)
    {
        try { if (File.Exists(path)) File.Delete(path); } catch (IOException) { } catch (UnauthorizedAccessException) { }
    }
}
