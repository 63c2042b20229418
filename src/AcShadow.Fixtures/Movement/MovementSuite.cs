namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One object Setup's movement cases, as one acshadow.movement-case/1 file holds them: the object in each
/// state the cases use (closed, open; "default" for an object without door states), the mover (with the
/// Setup it was read from) and the cases, in file order.
/// </summary>
public sealed record MovementSuite(
    uint SetupId,
    uint MoverSetupId,
    Mover Mover,
    IReadOnlyDictionary<string, MovementObject> Objects,
    IReadOnlyList<MovementCase> Cases);
