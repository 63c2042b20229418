using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One frame's transition: whether it was valid (a failed transition leaves the mover where it was), how many
/// steps it was cut into, where the mover's origin ended, and the state carried into the next frame
/// (contact plane, Contact and OnWalkable, the sliding normal) plus the last collision normal and whether
/// the object was hit; what the transition did (<see cref="Events"/>: stepUp, stepUpFailed, stepDown, slide,
/// slideStopped, walkOff, cliffSlide, precipiceSlide, edgeStop, land, landFailed) and the smallest margin of
/// its threshold decisions (<see cref="MinMargin"/>; infinity when it took none).
/// </summary>
public sealed record MovementFrame(
    int Frame,
    bool Valid,
    int Steps,
    Vector3 Position,
    bool Contact,
    bool OnWalkable,
    Plane? ContactPlane,
    Vector3? SlidingNormal,
    Vector3? CollisionNormal,
    bool HitObject)
{
    public IReadOnlyList<string> Events { get; init; } = [];

    public float MinMargin { get; init; } = float.PositiveInfinity;
}
