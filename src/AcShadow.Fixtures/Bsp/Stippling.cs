namespace AcShadow.Fixtures.Bsp;

/// <summary>Polygon stippling flags; NoPos/NoNeg say which UV index lists are absent.</summary>
[Flags]
public enum Stippling : byte
{
    None = 0x00,
    Positive = 0x01,
    Negative = 0x02,
    NoPos = 0x04,
    NoNeg = 0x08,
}
