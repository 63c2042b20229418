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
}
