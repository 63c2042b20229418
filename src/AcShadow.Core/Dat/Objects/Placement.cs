namespace AcShadow.Core.Dat.Objects;

/// <summary>Placement keys of a Setup's placement frames (retail names).</summary>
public static class Placement
{
    public const uint Default = 0x00;
    public const uint Resting = 0x65;

    private static readonly Dictionary<uint, string> Names = new()
    {
        [0x00] = "Default", [0x01] = "RightHandCombat", [0x02] = "RightHandNonCombat", [0x03] = "LeftHand",
        [0x04] = "Belt", [0x05] = "Quiver", [0x06] = "Shield", [0x07] = "LeftWeapon", [0x08] = "LeftUnarmed",
        [0x33] = "SpecialCrossbowBolt", [0x34] = "MissileFlight", [0x65] = "Resting", [0x66] = "Other",
        [0x67] = "Hook", [0x79] = "Random1", [0x7A] = "Random2", [0x7B] = "Random3", [0x7C] = "Random4",
        [0x7D] = "Random5", [0x7E] = "Random6", [0x7F] = "Random7", [0x80] = "Random8", [0x81] = "Random9",
        [0x82] = "Random10",
    };

    /// <summary>The retail name, or "Placement0xNN" for keys without one.</summary>
    public static string Name(uint key) => Names.TryGetValue(key, out var n) ? n : $"Placement0x{key:X2}";

    public static bool TryParse(string name, out uint key)
    {
        foreach (var (k, n) in Names)
            if (string.Equals(n, name, StringComparison.OrdinalIgnoreCase)) { key = k; return true; }
        if (name.StartsWith("Placement0x", StringComparison.OrdinalIgnoreCase)
            && uint.TryParse(name.AsSpan(11), System.Globalization.NumberStyles.HexNumber, null, out key)) return true;
        key = 0;
        return false;
    }
}
