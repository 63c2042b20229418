namespace AcShadow.Files;

/// <summary>A write would replace something that is not a regular file (a device, a FIFO, a socket, a symbolic link or a folder).</summary>
public sealed class NotARegularFileException(string path, FileKind kind)
    : IOException($"{path} is {FileKinds.Describe(kind)}, not a regular file: acshadow replaces only regular files")
{
    public string Path { get; } = path;
    public FileKind Kind { get; } = kind;
}
