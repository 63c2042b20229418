using System.Text.Json;

namespace AcShadow.Fixtures;

/// <summary>
/// The first thing every reader does: read <c>format</c> and refuse a version it does not know, saying
/// which one it reads and what to do, rather than misreading fields that may have changed meaning.
/// </summary>
internal static class FormatCheck
{
    public static void Require(JsonElement root, string expected, string what)
    {
        if (root.ValueKind != JsonValueKind.Object)
            throw new FormatException($"{what}: not a JSON object; expected a \"{expected}\" file");
        if (!root.TryGetProperty("format", out var f) || f.ValueKind != JsonValueKind.String)
            throw new FormatException($"{what}: no \"format\" field; expected \"{expected}\" (is this an acshadow file?)");
        var format = f.GetString()!;
        if (format == expected) return;
        var family = expected[..(expected.IndexOf('/') + 1)];
        throw new FormatException(format.StartsWith(family, StringComparison.Ordinal)
            ? $"{what}: format \"{format}\" is a version this library does not read (it reads \"{expected}\"); use the AcShadow.Fixtures release that matches the acshadow that wrote it, or regenerate the fixtures"
            : $"{what}: format \"{format}\" is not \"{expected}\"; wrong kind of file?");
    }
}
