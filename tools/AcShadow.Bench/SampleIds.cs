namespace AcShadow.Bench;

/// <summary>Ids in the forge's built-in sample that the benchmarks use.</summary>
public static class SampleIds
{
    /// <summary>The building GfxObj: 288 physics polygons, the sample's deepest BSP.</summary>
    public const uint House = 0x01005000;
}
