namespace AcShadow.Core.Dat.Objects;

[Flags]
public enum GfxObjFlags : uint
{
    None = 0,
    HasPhysics = 0x1,
    HasDrawing = 0x2,
    HasDIDDegrade = 0x8,
}
