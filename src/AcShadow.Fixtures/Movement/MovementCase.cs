using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One golden movement case (acshadow.movement-case/1): the object state it runs against, the walk (start on
/// the floor in contact, velocity at <see cref="Heading"/> degrees from the gate's normal, quantum, frames),
/// the gate plane it aims across, the reference's frames and outcome, and its stability: a fragile case (a
/// decision within 1e-5 of its threshold, or a class that changes when the start moves 1e-5 m or the speed
/// by a factor 1 ± 1e-5) is compared on <see cref="MovementOutcome.Class"/> only.
/// </summary>
public sealed record MovementCase(
    string Id,
    string State,
    float Heading,
    Walk Walk,
    Plane Gate,
    IReadOnlyList<MovementFrame> Expected,
    MovementOutcome Outcome,
    bool Fragile,
    float MinMargin);
