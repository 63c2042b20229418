namespace AcShadow.Core.Scenes;

/// <summary>
/// Where a landblock sits in the world: landblock 0xXXYY covers x ∈ [XX·192, XX·192 + 192) and likewise
/// for y (192 m a side). Computed in double: float32 world coordinates lose millimetres at these
/// magnitudes, which is why the dat stores frames landblock-relative.
/// </summary>
public readonly record struct LandblockCoordinates(int X, int Y)
{
    public const double Size = 192.0;

    public static LandblockCoordinates Of(uint landBlockInfoId) => new((int)(landBlockInfoId >> 24), (int)((landBlockInfoId >> 16) & 0xFF));

    public double WorldOriginX => X * Size;
    public double WorldOriginY => Y * Size;
}
