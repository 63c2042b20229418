namespace AcShadow.Core.Dat;

/// <summary>The header's data-set field: which database a dat file is.</summary>
public enum DatFileKind : uint
{
    Undefined = 0,
    Portal = 1,
    Cell = 2,
    Local = 3,
}
