namespace AcShadow.Core.Shapes;

/// <summary>What in the Setup a shape came from.</summary>
public enum ShapeSource
{
    Part,
    CylSphere,
    Sphere,
}
