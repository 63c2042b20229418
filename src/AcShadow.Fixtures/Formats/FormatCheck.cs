using System.Text.Json;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// The first thing every reader does: read <c>format</c> and refuse a version it does not know, saying
/// which one it reads and what to do, rather than misreading fields that may have changed meaning.
/// </summary>
internal static class FormatCheck
{
    public static void Require(JsonElement root, FileFormat format, string what)
    {
        var expected = format.Format;
        if (root.ValueKind != JsonValueKind.Object)
            throw new FormatException($"{what}: not a JSON object; expected a \"{expected}\" file");
        if (!root.TryGetProperty("format", out var f) || f.ValueKind != JsonValueKind.String)
            throw new FormatException($"{what}: no \"format\" field; expected \"{expected}\" (is this an acshadow file?)");
        var actual = f.GetString()!;
        if (actual == expected) return;
        var family = expected[..(expected.IndexOf('/') + 1)];
        throw new FormatException(actual.StartsWith(family, StringComparison.Ordinal)
            ? $"{what}: format \"{actual}\" is a version this library does not read (it reads \"{expected}\"); use the AcShadow.Fixtures release that matches the acshadow that wrote it, or regenerate the fixtures"
            : $"{what}: format \"{actual}\" is not \"{expected}\"; wrong kind of file?");
    }
}
