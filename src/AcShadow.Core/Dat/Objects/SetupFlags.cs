namespace AcShadow.Core.Dat.Objects;

[Flags]
public enum SetupFlags : uint
{
    None = 0,
    HasParent = 0x1,
    HasDefaultScale = 0x2,
    AllowFreeHeading = 0x4,
    HasPhysicsBsp = 0x8,
}
