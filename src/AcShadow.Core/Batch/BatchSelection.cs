using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Batch;

/// <summary>
/// What a batch (or audit) covers, as the user asked for it. The parts combine as a union:
/// the door catalog, every Setup in the dat, the ids of a setups file, and one landblock's scene.
/// <see cref="Landblock"/> is the LandBlockInfo id (0xXXYYFFFE).
/// </summary>
public sealed record BatchSelection(bool Doors, bool All, SetupList? Setups, uint? Landblock)
{
    public bool IsEmpty => !Doors && !All && Setups is null && Landblock is null;

    /// <summary>With a landblock: also its indoor cells (EnvCells); --no-cells clears it.</summary>
    public bool Cells { get; init; } = true;

    /// <summary>A short human description, e.g. "--doors --all --landblock 0xA9B4".</summary>
    public string Describe()
    {
        var parts = new List<string>();
        if (Doors) parts.Add("--doors");
        if (All) parts.Add("--all");
        if (Setups is not null) parts.Add($"--setups {Setups.Name}");
        if (Landblock is { } lb) parts.Add($"--landblock {LandblockIds.Short(lb)}");
        if (Landblock is not null && !Cells) parts.Add("--no-cells");
        return parts.Count == 0 ? "(nothing)" : string.Join(' ', parts);
    }
}

/// <summary>Landblock ids: users write 0xXXYY; the LandBlockInfo lives at 0xXXYYFFFE.</summary>
public static class LandblockIds
{
    /// <summary>Accepts 0xXXYY, XXYY or the full 0xXXYYFFFE; gives the LandBlockInfo id.</summary>
    public static bool TryParse(string? text, out uint landBlockInfoId)
    {
        landBlockInfoId = 0;
        if (string.IsNullOrWhiteSpace(text)) return false;
        var s = text.Trim();
        var digits = s.StartsWith("0x", StringComparison.OrdinalIgnoreCase) ? s[2..] : s;
        if (!JsonIds.TryParse(s, out var id)) return false;
        if (digits.Length <= 4) { landBlockInfoId = (id << 16) | 0xFFFE; return true; }
        if (digits.Length == 8 && (id & 0xFFFF) == 0xFFFE) { landBlockInfoId = id; return true; }
        return false;
    }

    /// <summary>"0xA9B4" for 0xA9B4FFFE.</summary>
    public static string Short(uint landBlockInfoId) => "0x" + (landBlockInfoId >> 16).ToString("X4", System.Globalization.CultureInfo.InvariantCulture);
}
