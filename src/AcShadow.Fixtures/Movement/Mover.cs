using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// The moving object as a transition sees it (OBJECTINFO::init, SPHEREPATH::init_sphere): its Setup's
/// spheres (the first two are used; none means retail's dummy sphere), step-up and step-down heights,
/// its scale, and whether it has EdgeSlide (a weenie property: PhysicsState 0x400000). Heights are the
/// Setup's; the reference multiplies spheres and heights by <see cref="Scale"/>, as OBJECTINFO does.
/// </summary>
public sealed record Mover(IReadOnlyList<Sphere> Spheres, float StepUpHeight, float StepDownHeight, float Scale = 1f)
{
    public bool EdgeSlide { get; init; } = true;

    /// <summary>
    /// Walks this mover against <paramref name="obstacle"/> (null: the bare floor), frame by frame, as the retail
    /// client moves it: acshadow's movement reference, the one that wrote the movement cases.
    /// </summary>
    public IReadOnlyList<MovementFrame> Run(MovementObject? obstacle, Walk walk) => MovementReference.Run(this, obstacle, walk);
}
