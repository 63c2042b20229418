using System.Globalization;

namespace AcShadow.Fixtures.Json;

/// <summary>Dat ids in the formats are "0x%08X" strings.</summary>
internal static class JsonIds
{
    public static string Format(uint id) => "0x" + id.ToString("X8", CultureInfo.InvariantCulture);

    /// <summary>Accepts "0x020019FF" or "020019FF" (1–8 hex digits).</summary>
    public static bool TryParse(string? text, out uint id)
    {
        id = 0;
        if (string.IsNullOrWhiteSpace(text)) return false;
        var s = text.Trim();
        if (s.StartsWith("0x", StringComparison.OrdinalIgnoreCase)) s = s[2..];
        if (s.Length is 0 or > 8) return false;
        return uint.TryParse(s, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out id);
    }
}
