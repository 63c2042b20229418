using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>An object made of shapes: blocked when any of them blocks (CPhysicsObj::FindObjCollisions over its parts).</summary>
internal sealed class AnyOverlap(IReadOnlyList<ISphereOverlap> shapes) : ISphereOverlap
{
    private readonly ISphereOverlap[] _shapes = [.. shapes];

    public IReadOnlyList<ISphereOverlap> Shapes => _shapes;

    public bool Overlaps(Vector3 center, float radius)
    {
        foreach (var shape in _shapes)
            if (shape.Overlaps(center, radius)) return true;
        return false;
    }
}
