using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// One placed object of a scene as a query: its landblock-relative frame (the entity's position and unit
/// rotation; the client turns the moving sphere into each object's frame), its collision in entity
/// space, and an entity-space sphere around everything it can block, for the broad phase.
/// </summary>
internal sealed class PlacedQuery
{
    private readonly Vector3 _boundInLandblock;

    public int Index { get; }
    public uint Id { get; }
    public PartPose Frame { get; }
    public ISphereOverlap EntityQuery { get; }
    public Vector3 BoundCenter { get; }
    public float BoundRadius { get; }

    public PlacedQuery(int index, uint id, Vector3 position, Quaternion rotation, ISphereOverlap entityQuery, Vector3 boundCenter, float boundRadius)
    {
        var length = MathF.Sqrt(rotation.X * rotation.X + rotation.Y * rotation.Y + rotation.Z * rotation.Z + rotation.W * rotation.W);
        if (!(length > 1e-6f) || !float.IsFinite(length)) rotation = Quaternion.Identity;
        else rotation = new Quaternion(rotation.X / length, rotation.Y / length, rotation.Z / length, rotation.W / length);
        Index = index;
        Id = id;
        Frame = new PartPose(position, rotation, 1f);
        EntityQuery = entityQuery;
        BoundCenter = boundCenter;
        BoundRadius = boundRadius;
        _boundInLandblock = Frame.ToEntity(boundCenter);
    }

    /// <summary>The bounding sphere in the landblock's frame, as <see cref="Overlaps"/> tests it first.</summary>
    public (Vector3 Center, float Radius) LandblockBound => (_boundInLandblock, BoundRadius);

    /// <summary>Does a sphere at this landblock-relative centre touch the object?</summary>
    public bool Overlaps(Vector3 center, float radius)
    {
        float dx = center.X - _boundInLandblock.X, dy = center.Y - _boundInLandblock.Y, dz = center.Z - _boundInLandblock.Z;
        var sum = BoundRadius + radius;
        if (!(dx * dx + dy * dy + dz * dz <= sum * sum)) return false;
        var (local, r) = Frame.ToLocal(center, radius);
        return EntityQuery.Overlaps(local, r);
    }
}
