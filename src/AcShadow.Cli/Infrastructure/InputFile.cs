using AcShadow.Files;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// A file acshadow reads must be a regular file (or a link to one), asked before it is opened: opening a FIFO
/// waits for a writer forever, and a device never ends.
/// </summary>
internal static class InputFile
{
    /// <summary>Refuses <paramref name="path"/> unless it is a regular file, naming <paramref name="option"/> and the fix.</summary>
    public static void RequireRegular(string path, int exitCode, string option, string fix) =>
        RequireRegular(path, FileKinds.Of(path, followLinks: true), exitCode, option, fix);

    /// <summary>As above, for a caller that has already asked what <paramref name="path"/> is.</summary>
    public static void RequireRegular(string path, FileKind kind, int exitCode, string option, string fix)
    {
        if (kind is not (FileKind.Regular or FileKind.Unknown))
            throw new CliException(exitCode, $"{option}: {path} is {FileKinds.Describe(kind)}, not a regular file: {fix}");
    }

    /// <summary>
    /// The most a file acshadow wrote may hold when it is read back (a shadow file, BSP dump, cell file, index):
    /// the largest a real dat gives is a few MiB, and each is read whole, so a file past this is refused before
    /// it is read instead of growing the process by ten times its size.
    /// </summary>
    public const long MaxFixtureBytes = 64L << 20;

    /// <summary>The most a compiled-scene.json may hold (a real landblock's is tens of MiB at most).</summary>
    public const long MaxSceneBytes = 256L << 20;

    /// <summary>Refuses <paramref name="path"/> when it is larger than <paramref name="maxBytes"/>, naming the limit.</summary>
    public static void RequireAtMost(string path, long maxBytes, int exitCode, string option)
    {
        var length = new FileInfo(path).Length;
        if (length > maxBytes)
            throw new CliException(exitCode, $"{option}: {path} is {length >> 20} MiB, more than the {maxBytes >> 20} MiB acshadow reads back from one file (docs/errors.md, \"Limits\"): it is not a file acshadow wrote");
    }
}
