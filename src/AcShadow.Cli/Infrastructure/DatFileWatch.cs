using AcShadow.Files;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// What a dat file was when it was opened (its length, its last write, which file the path named), so a
/// run can tell that the file changed under it: a dat truncated, rewritten or replaced while a run reads it
/// gives garbage that looks like corrupt objects, and the run must stop rather than skip them one by one.
/// </summary>
public sealed class DatFileWatch
{
    private readonly string _path;
    private readonly FileStream _stream;
    private readonly long _length;
    private readonly DateTime _written;
    private readonly byte[]? _identity;

    public DatFileWatch(string path, FileStream stream)
    {
        _path = path;
        _stream = stream;
        _length = RandomAccess.GetLength(stream.SafeFileHandle);
        _written = File.GetLastWriteTimeUtc(path);
        _identity = FileKinds.Identity(stream.SafeFileHandle);
    }

    /// <summary>The file's device and inode numbers when it was opened (<see cref="FileKinds.Identity(string)"/>); null where the platform cannot say.</summary>
    public byte[]? Identity => _identity;

    /// <summary>How the file changed since it was opened, or null when it did not.</summary>
    public string? Change()
    {
        try
        {
            var length = RandomAccess.GetLength(_stream.SafeFileHandle);
            if (length != _length) return $"{_path} changed from {_length} to {length} bytes";
            if (FileKinds.Identity(_path) is { } now && _identity is not null && !now.AsSpan().SequenceEqual(_identity))
                return $"{_path} was replaced by another file";
            if (File.GetLastWriteTimeUtc(_path) != _written) return $"{_path} was rewritten";
            return null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ObjectDisposedException)
        {
            return $"{_path} can no longer be read ({e.Message})";
        }
    }
}
