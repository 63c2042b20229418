namespace AcShadow.Fixtures.Bsp;

/// <summary>
/// A polygon's cull mode as stored in the dat, with DatReaderWriter's names. What the values mean:
/// 0 single-sided (ACE calls it Clockwise), 1 double-sided, 2 double-sided with its own negative
/// surface and UV indices (ACE: Unknown). Only 2 stores negative UVs.
/// </summary>
public enum SidesType
{
    Landblock = 0,
    None = 1,
    Clockwise = 2,
    CounterClockwise = 3,
}
