using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// What the mover does: it starts standing at <see cref="Start"/> (its origin, landblock-local) on a flat
/// floor at <see cref="FloorZ"/>, or on whatever walkable surface is under it when <see cref="StartContact"/>
/// names one, and for <see cref="Frames"/> frames of <see cref="Quantum"/> seconds moves at the horizontal
/// <see cref="Velocity"/>, falling under gravity whenever it is not on walkable ground. Heading stays fixed.
/// </summary>
public sealed record Walk(Vector3 Start, Vector3 Velocity, float FloorZ, int Frames, float Quantum = 1f / 30f)
{
    /// <summary>The contact plane the mover starts on (null: the floor).</summary>
    public Plane? StartContact { get; init; }
}
