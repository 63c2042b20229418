using System.Buffers;
using System.Security.Cryptography;
using Microsoft.Win32.SafeHandles;

namespace AcShadow.Files;

/// <summary>Whether a file on disk still holds the bytes a run recorded for it: its length and its SHA-256.</summary>
public static class FileDigest
{
    /// <summary>
    /// True when <paramref name="path"/> is a regular file of <paramref name="bytes"/> bytes whose SHA-256 is
    /// <paramref name="sha256"/> (lower-case hex): the hash, not only the size, since a same-length edit keeps the
    /// size. A link, a FIFO or anything but a regular file never holds them (and is not opened: a FIFO would wait).
    /// </summary>
    public static bool Holds(string path, long bytes, string sha256)
    {
        if (FileKinds.Of(path) != FileKind.Regular) return false;
        try
        {
            using var handle = File.OpenHandle(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
            return RandomAccess.GetLength(handle) == bytes && Convert.ToHexStringLower(Sha256Of(handle)) == sha256;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    /// <summary>
    /// A file's SHA-256 read through one rented buffer: a stream's own 64 KB buffer for each of an incremental batch's
    /// previous files (22,354 on the scale dat) was 1.4 GB of garbage, and a quarter of the run went to collecting it.
    /// </summary>
    private static byte[] Sha256Of(SafeFileHandle handle)
    {
        using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        var buffer = ArrayPool<byte>.Shared.Rent(1 << 18);
        try
        {
            long at = 0;
            int read;
            while ((read = RandomAccess.Read(handle, buffer, at)) > 0)
            {
                hash.AppendData(buffer, 0, read);
                at += read;
            }
            return hash.GetHashAndReset();
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(buffer);
        }
    }
}
