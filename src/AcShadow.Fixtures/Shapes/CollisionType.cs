using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Shapes;

/// <summary>How a shape collides: a part's PhysicsBSP, a vertical cylinder, or a sphere.</summary>
public enum CollisionType
{
    Bsp,
    Cylinder,
    Sphere,
}
