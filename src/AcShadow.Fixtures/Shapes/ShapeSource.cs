using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Shapes;

/// <summary>What in the Setup a shape came from.</summary>
public enum ShapeSource
{
    Part,
    CylSphere,
    Sphere,
}
