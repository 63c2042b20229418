using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Formats;

/// <summary>The names a shadow file gives a shape's source and collision type, for its writer and its reader.</summary>
internal static class ShadowShapeNames
{
    public static string Name(this ShapeSource s) => s switch
    {
        ShapeSource.Part => "part",
        ShapeSource.CylSphere => "cylSphere",
        _ => "sphere",
    };

    public static string Name(this CollisionType t) => t switch
    {
        CollisionType.Bsp => "bsp",
        CollisionType.Cylinder => "cylinder",
        _ => "sphere",
    };

    public static ShapeSource ParseSource(string name) => name switch
    {
        "part" => ShapeSource.Part,
        "cylSphere" => ShapeSource.CylSphere,
        "sphere" => ShapeSource.Sphere,
        _ => throw new FormatException($"unknown shape source \"{name}\""),
    };

    public static CollisionType ParseCollisionType(string name) => name switch
    {
        "bsp" => CollisionType.Bsp,
        "cylinder" => CollisionType.Cylinder,
        "sphere" => CollisionType.Sphere,
        _ => throw new FormatException($"unknown collision type \"{name}\""),
    };
}
