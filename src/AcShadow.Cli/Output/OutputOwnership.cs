using System.Text;

namespace AcShadow.Cli.Output;

/// <summary>
/// Whether an existing file is acshadow's to replace: its first line holding a letter must be the one
/// acshadow writes there, digits aside. That is the format declaration of a JSON file
/// (<c>"format": "acshadow.shadow/2",</c>; acdream's <c>"GfxObjId": …</c>), a CSV's header row, an SVG's
/// root element; the digits may differ (versions, ids, sizes), nothing else (on a line that declares a
/// format, only the declaration counts). A user's own file of the
/// same name differs there, and is left alone. A binary glTF file (<c>view</c>'s .glb) has no lines: it is
/// ours when it starts with the glTF magic and its JSON names acshadow as its generator.
/// </summary>
public static class OutputOwnership
{
    /// <summary>The signature line must lie within this many bytes of the start.</summary>
    public const int HeadBytes = 4096;

    public static bool IsOurs(ReadOnlySpan<byte> existingHead, ReadOnlySpan<byte> newContent)
    {
        if (IsGlb(newContent)) return IsGlb(existingHead) && existingHead.IndexOf(GlbGenerator) >= 0;
        var ours = Signature(newContent);
        return ours is not null && ours == Signature(existingHead);
    }

    private static ReadOnlySpan<byte> GlbGenerator => "\"generator\":\"acshadow view\""u8;

    private static bool IsGlb(ReadOnlySpan<byte> bytes) => bytes.StartsWith("glTF"u8);

    /// <summary>
    /// A line declaring a format, as only that declaration: the canonical writer puts a small object on one
    /// line (an incremental.json with no Setups is <c>{"format": …, "tool": …, "setups": [], …}</c>), and the
    /// rest of such a line (a tool key, a checksum) says nothing about whose file it is.
    /// </summary>
    private static string FormatDeclaration(string line)
    {
        const string declaration = "\"format\": \"";
        var at = line.IndexOf(declaration, StringComparison.Ordinal);
        var end = at < 0 ? -1 : line.IndexOf('"', at + declaration.Length);
        return end < 0 ? line : line[at..(end + 1)];
    }

    private static string? Signature(ReadOnlySpan<byte> bytes)
    {
        var text = Encoding.UTF8.GetString(bytes[..Math.Min(bytes.Length, HeadBytes)]);
        foreach (var line in text.Split('\n'))
        {
            if (!line.Any(char.IsAsciiLetter)) continue;
            return new string(FormatDeclaration(line.TrimEnd('\r')).Where(c => !char.IsAsciiDigit(c)).ToArray());
        }
        return null;
    }
}
