using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A sphere against a solid <see cref="OrientedBox"/>, in the box's part space, by true distance and
/// retail's conventions (the ones a BSP of the same box answers with): the sphere shrinks by
/// <see cref="PhysicsEpsilon"/> (reach = r − ε); a face the shrunk sphere only touches is clear
/// (BSPNODE::sphere_intersects_solid sends dist ≥ reach to the positive side alone, where the solid and
/// the face's polygon are not); an edge or corner it touches blocks (CPolygon::polygon_hits_sphere_precise
/// counts the disc reaching the boundary); a centre inside blocks (the solid leaf's centre check).
/// </summary>
internal sealed class BoxSphereQuery(OrientedBox box) : ISphereOverlap
{
    public OrientedBox Box { get; } = box;

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius)) return false;
        // Into the fitted box's own axes: a model with no client counterpart (see OrientedBox), so the plain rotation.
        var q = QuaternionRotation.RotateInverse(Box.Axes, Vec.Sub(center, Box.Center));
        var ex = MathF.Abs(q.X) - Box.HalfExtents.X;
        var ey = MathF.Abs(q.Y) - Box.HalfExtents.Y;
        var ez = MathF.Abs(q.Z) - Box.HalfExtents.Z;
        var reach = radius - PhysicsEpsilon.Value;
        if (MathF.Max(ex, MathF.Max(ey, ez)) >= reach) return false;
        // Beyond the faces it is out of, the distance to the box is the length of the excess.
        float ox = MathF.Max(ex, 0f), oy = MathF.Max(ey, 0f), oz = MathF.Max(ez, 0f);
        return ox * ox + oy * oy + oz * oz <= reach * reach;
    }
}
