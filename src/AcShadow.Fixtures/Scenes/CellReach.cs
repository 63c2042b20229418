using System.Numerics;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// An indoor cell's broad phase in the landblock's frame, before the sphere is turned into the cell's frame:
/// the tree's root sphere (<see cref="Collision.CellOverlapQuery.Bound"/>) widened by 0.05 m and 0.1 % of the
/// mover's radius, more than the root test's ε (at most 0.015 m) and every rounding of the turn, so it
/// rejects only spheres the root would reject. A mover outdoors asks a dungeon below it one distance, not a
/// turn (which the client avoids by never reaching the dungeon from outside).
/// </summary>
internal readonly record struct CellReach(Vector3 Center, float Radius, bool Always)
{
    public static CellReach Of((Vector3 Center, float Radius)? bound) =>
        bound is { } b && float.IsFinite(b.Center.X) && float.IsFinite(b.Center.Y) && float.IsFinite(b.Center.Z) && float.IsFinite(b.Radius)
            ? new CellReach(b.Center, b.Radius + 0.05f, false)
            : new CellReach(Vector3.Zero, 0f, true);

    /// <summary><see cref="Reaches"/> over a box of centres.</summary>
    public Collision.BoxDecision ReachesOver(in Collision.CentreBox box, float radius) =>
        Always ? Collision.BoxDecision.True : box.Within(Center, Radius + radius * 1.001f);

    public bool Reaches(Vector3 center, float radius)
    {
        if (Always) return true;
        float dx = center.X - Center.X, dy = center.Y - Center.Y, dz = center.Z - Center.Z, sum = Radius + radius * 1.001f;
        return dx * dx + dy * dy + dz * dz <= sum * sum;
    }
}
