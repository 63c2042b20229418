namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A cell portal's flags (a ushort in the dat). ACE reads PortalSide as "the flag is clear"
/// (CellPortal.PortalSide), so the raw bit is kept and the meaning left to the consumer.
/// </summary>
[Flags]
public enum PortalFlags : ushort
{
    None = 0,
    ExactMatch = 0x1,
    PortalSide = 0x2,
}
