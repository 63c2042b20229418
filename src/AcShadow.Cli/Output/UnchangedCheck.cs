using System.Buffers;
using AcShadow.Files;
using Microsoft.Win32.SafeHandles;

namespace AcShadow.Cli.Output;

/// <summary>
/// Whether a file already holds exactly the bytes a run would write: then it is left alone (its timestamp
/// kept, no new inode). One open and chunked reads into a pooled buffer: a batch asks this of every file.
/// </summary>
public static class UnchangedCheck
{
    public static bool IsUnchanged(string root, string relativePath, ReadOnlySpan<byte> content)
    {
        var target = OutputPaths.Target(root, relativePath);
        // Asked before opening: opening a FIFO waits for a writer. A device, FIFO or link is "changed", so
        // the write that follows refuses it; a missing file costs this one call instead of a failed open.
        if (FileKinds.Of(target) != FileKind.Regular) return false;
        SafeFileHandle handle;
        try
        {
            handle = File.OpenHandle(target, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
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
}
