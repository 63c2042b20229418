namespace AcShadow.Fixtures.Json;

/// <summary>Names shared by the BSP dump writer and reader.</summary>
public static class BspFileFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.Bsp;

    /// <summary>Relative path of a GfxObj's dump inside an output folder.</summary>
    public static string PathFor(uint gfxObjId) => $"gfxobjs/{JsonIds.Format(gfxObjId)}.bsp.json";
}
