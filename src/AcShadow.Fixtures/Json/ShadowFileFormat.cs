namespace AcShadow.Fixtures.Json;

/// <summary>Names shared by the shadow file writer and reader.</summary>
public static class ShadowFileFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.Shadow;

    /// <summary>Relative path of a Setup's shadow file inside an output folder.</summary>
    public static string PathFor(uint setupId) => $"setups/{JsonIds.Format(setupId)}.shadow.json";

    /// <summary>A BSP dump's path relative to a shadow file (setups/ and gfxobjs/ are siblings).</summary>
    public static string BspReference(uint gfxObjId) => "../" + BspFileFormat.PathFor(gfxObjId);

    public static string SourceName(Shapes.ShapeSource s) => s switch
    {
        Shapes.ShapeSource.Part => "part",
        Shapes.ShapeSource.CylSphere => "cylSphere",
        _ => "sphere",
    };

    public static string CollisionTypeName(Shapes.CollisionType t) => t switch
    {
        Shapes.CollisionType.Bsp => "bsp",
        Shapes.CollisionType.Cylinder => "cylinder",
        _ => "sphere",
    };
}
