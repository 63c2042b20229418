namespace AcShadow.Core.Dat;

/// <summary>The object types acshadow reads, and the id range each lives in.</summary>
public enum DatObjectKind
{
    GfxObj,
    Setup,
    LandBlockInfo,
    MotionTable,
    Animation,
    /// <summary>An indoor cell (cell dat, 0xXXYY0100-0xXXYYFFFD).</summary>
    EnvCell,
    /// <summary>The cell shapes EnvCells use (portal dat, 0x0D000000-0x0D00FFFF).</summary>
    Environment,
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
        DatObjectKind.EnvCell => (id & 0xFFFF) is >= 0x0100 and <= 0xFFFD,
        DatObjectKind.Environment => id is >= 0x0D000000 and <= 0x0D00FFFF,
        _ => false,
    };

    public static string RangeText(this DatObjectKind kind) => kind switch
    {
        DatObjectKind.GfxObj => "0x01000000-0x0100FFFF",
        DatObjectKind.Setup => "0x02000000-0x0200FFFF",
        DatObjectKind.LandBlockInfo => "0xXXYYFFFE",
        DatObjectKind.MotionTable => "0x09000000-0x0900FFFF",
        DatObjectKind.Animation => "0x03000000-0x0300FFFF",
        DatObjectKind.EnvCell => "0xXXYY0100-0xXXYYFFFD",
        DatObjectKind.Environment => "0x0D000000-0x0D00FFFF",
        _ => "?",
    };
}
