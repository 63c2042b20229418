namespace AcShadow.Core.Dat.Objects;

/// <summary>An EnvCell's flags (DatReaderWriter's EnvCellFlags; ACE's EnvCellFlags).</summary>
[Flags]
public enum EnvCellFlags : uint
{
    None = 0,
    SeenOutside = 0x1,
    HasStaticObjs = 0x2,
    HasRestrictionObj = 0x8,
}
