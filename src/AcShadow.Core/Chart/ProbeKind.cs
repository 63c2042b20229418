namespace AcShadow.Core.Chart;

public enum ProbeKind
{
    /// <summary>A point of the 3-D grid around the object.</summary>
    Grid,
    /// <summary>A point on a line across the doorway at walking height.</summary>
    Doorway,
}
