namespace AcShadow.Core.Dat;

/// <summary>The object types acshadow reads, and the id range each lives in.</summary>
public enum DatObjectKind
{
    GfxObj,
    Setup,
    LandBlockInfo,
    MotionTable,
    Animation,
}

public static class DatObjectKinds
{
    public static bool Contains(this DatObjectKind kind, uint id) => kind switch
    {
        DatObjectKind.GfxObj => id is >= 0x01000000 and <= 0x0100FFFF,
        DatObjectKind.Setup => id is >= 0x02000000 and <= 0x0200FFFF,
        DatObjectKind.LandBlockInfo => (id & 0xFFFF) == 0xFFFE,
        DatObjectKind.MotionTable => id is >= 0x09000000 and <= 0x0900FFFF,
        DatObjectKind.Animation => id is >= 0x03000000 and <= 0x0300FFFF,
        _ => false,
    };

    public static string RangeText(this DatObjectKind kind) => kind switch
    {
        DatObjectKind.GfxObj => "0x01000000-0x0100FFFF",
        DatObjectKind.Setup => "0x02000000-0x0200FFFF",
        DatObjectKind.LandBlockInfo => "0xXXYYFFFE",
        DatObjectKind.MotionTable => "0x09000000-0x0900FFFF",
        DatObjectKind.Animation => "0x03000000-0x0300FFFF",
        _ => "?",
    };
}
