using System.Numerics;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A part-space query placed by its part's pose: the sphere is moved into part space first
/// (<see cref="PartPose.ToLocal"/>, CSpherePath::CacheLocalSpaceSphere), so ε applies in part units as it
/// does for the part's BSP.
/// </summary>
internal sealed class PosedQuery(PartPose pose, ISphereOverlap partQuery) : ISphereOverlap
{
    public PartPose Pose { get; } = pose;
    public ISphereOverlap PartQuery { get; } = partQuery;

    public bool Overlaps(Vector3 center, float radius)
    {
        var (local, localRadius) = Pose.ToLocal(center, radius);
        return PartQuery.Overlaps(local, localRadius);
    }
}
