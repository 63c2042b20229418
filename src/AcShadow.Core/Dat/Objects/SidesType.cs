namespace AcShadow.Core.Dat.Objects;

/// <summary>A polygon's cull mode as stored in the dat (DatReaderWriter's CullMode values).</summary>
public enum SidesType
{
    Landblock = 0,
    None = 1,
    Clockwise = 2,
    CounterClockwise = 3,
}
