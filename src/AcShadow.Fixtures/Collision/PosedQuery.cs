using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// A part-space query placed by its part's pose: the sphere is moved into part space first
/// (<see cref="PartPose.ToLocal(Vector3, float)"/>, CSpherePath::CacheLocalSpaceSphere), so ε applies in part units as it
/// does for the part's BSP. A sphere beyond the part's <see cref="Reach"/> in the entity frame is refused
/// before the turn; the part-local test decides the rest, so answers are the turned test's.
/// </summary>
internal sealed class PosedQuery : ISphereOverlap
{
    private readonly ClientFrameMatrix _matrix;

    private readonly bool _refuses;

    /// <param name="pose">The part's pose in the entity.</param>
    /// <param name="partQuery">The part's test in its own space.</param>
    /// <param name="refuseByReach">Refuse spheres beyond <see cref="Reach"/> unturned; false where a caller has refused them already (a part registered on its own behind its reach, <see cref="Scenes.PlacedParts"/>).</param>
    public PosedQuery(PartPose pose, ISphereOverlap partQuery, bool refuseByReach = true)
    {
        Pose = pose;
        PartQuery = partQuery;
        _matrix = pose.Matrix;
        Reach = PartReach.Of(pose, LocalBound.Of(partQuery));
        _refuses = refuseByReach && Reach.IsBounded;
    }

    public PartPose Pose { get; }

    /// <summary>Whether <see cref="Overlaps"/> refuses by <see cref="Reach"/> before the turn (a placed part's entry has refused already).</summary>
    public bool RefusesByReach => _refuses;
    public ISphereOverlap PartQuery { get; }

    /// <summary>Where in the entity frame the part can block (<see cref="PartReach.Everywhere"/> for a part query without a known bound).</summary>
    public PartReach Reach { get; }

    public bool Overlaps(Vector3 center, float radius)
    {
        if (_refuses && !Reach.Reaches(center, radius)) return false;
        var (local, localRadius) = Pose.ToLocal(_matrix, center, radius);
        return PartQuery.Overlaps(local, localRadius);
    }
}
