using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// One placed object of a scene as a query: its landblock-relative frame (the entity's position and its rotation
/// as the client holds it, <see cref="ClientFrameMatrix.PlacedRotation"/>; the client turns the moving sphere into
/// each object's frame), its collision in entity
/// space, and an entity-space sphere around everything it can block, for the broad phase. The compiled scene places
/// each part of an object as one of these (<see cref="PlacedParts"/>), behind the part's own sphere.
/// </summary>
internal sealed class PlacedQuery
{
    private readonly Vector3 _boundInLandblock;
    private readonly float _stretch;
    private readonly float _reach;
    private readonly ClientFrameMatrix _matrix;

    public int Index { get; }
    public uint Id { get; }
    public PartPose Frame { get; }
    public ISphereOverlap EntityQuery { get; }
    public Vector3 BoundCenter { get; }
    public float BoundRadius { get; }

    /// <summary>Which of the object's shapes (in its model's order) <see cref="EntityQuery"/> asks; null: all of them.</summary>
    public IReadOnlyList<int>? Shapes { get; init; }

    /// <summary>An object (or one part of it) behind an entity-space bound; <paramref name="radiusStretch"/> is the factor the bound puts on the query radius (<see cref="PartReach.Stretch"/>; <see cref="BoundStretch"/> for an object's sphere, √2 with a cylinder; 1 for a plain sphere).</summary>
    public PlacedQuery(int index, uint id, Vector3 position, Quaternion rotation, ISphereOverlap entityQuery, Vector3 boundCenter, float boundRadius, float radiusStretch = 1f)
    {
        Index = index;
        Id = id;
        Frame = new PartPose(position, ClientFrameMatrix.PlacedRotation(rotation), 1f);
        _matrix = Frame.Matrix;
        FrameKey = this;
        EntityQuery = entityQuery;
        BoundCenter = boundCenter;
        BoundRadius = boundRadius;
        _boundInLandblock = Frame.ToEntity(boundCenter);
        // A stored quaternion of squared length s gives the matrix s·R + (1 − s)·I: it moves a point up to 2|1 − s|
        // times its distance from the origin away from the pure rotation, both ways. The broad phase widens by that
        // much (zero for a unit quaternion) so it never refuses what the narrow phase would block.
        var q = Frame.Rotation;
        var off = 4.0 * Math.Abs(1.0 - ((double)q.W * q.W + (double)q.X * q.X + (double)q.Y * q.Y + (double)q.Z * q.Z));
        _stretch = (float)((1.0 + off) * radiusStretch);
        var fromOrigin = Math.Sqrt((double)boundCenter.X * boundCenter.X + (double)boundCenter.Y * boundCenter.Y + (double)boundCenter.Z * boundCenter.Z);
        _reach = (float)(boundRadius + off * (boundRadius + fromOrigin));
    }

    /// <summary>The bounding sphere in the landblock's frame, as <see cref="Overlaps"/> tests it first (with the mover's radius times <see cref="RadiusStretch"/>).</summary>
    public (Vector3 Center, float Radius) LandblockBound => (_boundInLandblock, BoundRadius);

    /// <summary>
    /// The sphere <see cref="Near"/> passes within for a zero radius, in the landblock's frame: the bound widened by
    /// what a not quite unit quaternion moves it (nothing for a unit one), as a partition registers the entry.
    /// </summary>
    public (Vector3 Center, float Radius) LandblockReach => (_boundInLandblock, _reach);

    /// <summary>The factor <see cref="Near"/> puts on the mover's radius (at least 1): a partition pads a mover's range by it.</summary>
    public float RadiusStretch => _stretch;

    /// <summary>
    /// Entries that share this key stand in the same frame (the parts of one object, <see cref="PlacedParts"/>): a walk
    /// may turn a sphere once for all of them, since the turn is the same float operations each time.
    /// </summary>
    public object FrameKey { get; init; }

    /// <summary>
    /// For one part of an object registered apart, the whole object behind its own sphere: a walk asks it first, once
    /// per frame, so a sphere away from the object costs one test however many of its parts a land cell holds.
    /// </summary>
    public PlacedQuery? Whole { get; init; }

    /// <summary>Does a sphere at this landblock-relative centre touch the object?</summary>
    public bool Overlaps(Vector3 center, float radius)
    {
        if (!Near(center, radius)) return false;
        var (local, r) = ToEntity(center, radius);
        return EntityQuery.Overlaps(local, r);
    }

    /// <summary>The broad phase: is the sphere within the bound (so <see cref="EntityQuery"/> may block it)?</summary>
    public bool Near(Vector3 center, float radius)
    {
        float dx = center.X - _boundInLandblock.X, dy = center.Y - _boundInLandblock.Y, dz = center.Z - _boundInLandblock.Z;
        var sum = _reach + radius * _stretch;
        return dx * dx + dy * dy + dz * dz <= sum * sum;
    }

    /// <summary><see cref="Near"/> over a box of centres (<see cref="CentreBox.Within"/>), and the distance it tests within (infinite or NaN: none).</summary>
    public BoxDecision NearOver(in CentreBox box, float radius) => box.Within(_boundInLandblock, NearDistance(radius));

    /// <summary>The distance from <see cref="LandblockBound"/>'s centre within which <see cref="Near"/> passes, as it computes it.</summary>
    public float NearDistance(float radius) => _reach + radius * _stretch;

    /// <summary>The matrix <see cref="ToEntity"/> turns with.</summary>
    public ClientFrameMatrix Matrix => _matrix;

    /// <summary>The sphere in the object's frame (Frame::globaltolocal with the matrix built once).</summary>
    public (Vector3 Center, float Radius) ToEntity(Vector3 center, float radius) => Frame.ToLocal(_matrix, center, radius);
}
