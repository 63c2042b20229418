using System.Text;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Formats;
using AcShadow.Files;

namespace AcShadow.Cli.Output;

/// <summary>
/// Refuses, before anything is written, to replace a file acshadow does not recognise as its own
/// (<see cref="OutputOwnership"/>) and that the folder's own index.json does not list, naming it; a
/// folder, link, FIFO, device or socket where a file belongs is refused the same way, listed or not, and
/// is never opened (opening a FIFO waits for a writer).
/// </summary>
public static class ForeignFileGuard
{
    public static void Refuse(string root, IEnumerable<OutputFile> files,
        IReadOnlySet<string>? listedAsOurs = null, string option = "--out")
    {
        var foreign = new List<string>();
        foreach (var (relative, content) in files)
        {
            var target = OutputPaths.Target(root, relative);
            switch (FileKinds.Of(target))
            {
                case FileKind.Missing:
                    break;
                case FileKind.Regular or FileKind.Unknown:
                    if (listedAsOurs?.Contains(relative) != true && !OutputOwnership.IsOurs(ReadHead(target), content.Span)) foreign.Add(target);
                    break;
                case var kind:
                    foreign.Add($"{target} ({FileKinds.Describe(kind)})");
                    break;
            }
        }
        if (foreign.Count == 0) return;
        throw new CliException(ExitCodes.OutputFailed,
            $"{option}: {foreign[0]}{(foreign.Count > 1 ? $" and {foreign.Count - 1} more" : "")} would be replaced but {(foreign.Count > 1 ? "are" : "is")} not acshadow output: " +
            "move it away or pass another folder; nothing was written");
    }

    /// <summary>Whether the regular file at <paramref name="path"/> starts as a file of <paramref name="content"/>'s kind would (<see cref="OutputOwnership"/>).</summary>
    public static bool IsOurs(string path, ReadOnlySpan<byte> content) =>
        FileKinds.Of(path) == FileKind.Regular && OutputOwnership.IsOurs(ReadHead(path), content);

    /// <summary>The start of a format's first line, as a file of that format would begin: for checking files not yet made.</summary>
    public static ReadOnlyMemory<byte> JsonHead(string format) => Encoding.UTF8.GetBytes($"{{\n  \"format\": \"{format}\",\n");

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
}
