using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures;

/// <summary>
/// A <see cref="SetupFixture"/> at a world position and rotation. A world-space query sphere is moved into
/// the entity's frame (Frame::globaltolocal; the radius is unchanged) and asked there, as the client transforms
/// the moving sphere into each object's frame. The rotation is kept as given when Frame::IsValid accepts it (the
/// client does not normalise a frame it reads), else normalised as Frame::set_rotate does.
/// </summary>
public sealed class PlacedFixture
{
    private readonly PartPose _frame;

    public SetupFixture Fixture { get; }
    public Vector3 Position => _frame.Position;
    public Quaternion Rotation => _frame.Rotation;

    internal PlacedFixture(SetupFixture fixture, Vector3 position, Quaternion rotation)
    {
        var length = rotation.Length();
        if (!float.IsFinite(length) || length < 1e-6f || !float.IsFinite(position.X + position.Y + position.Z))
            throw new ArgumentException($"a world frame needs a finite position and a non-zero rotation; got {position}, {rotation}");
        Fixture = fixture;
        _frame = new PartPose(position, ClientFrameMatrix.PlacedRotation(rotation), 1f);
    }

    /// <summary>Does a sphere at this world-space centre and radius touch the placed object?</summary>
    public bool Overlaps(Vector3 worldCenter, float radius)
    {
        var (center, r) = _frame.ToLocal(worldCenter, radius);
        return Fixture.Overlaps(center, r);
    }

    /// <summary>A world-space point in the entity's frame.</summary>
    public Vector3 ToEntity(Vector3 worldPoint) => _frame.ToLocal(worldPoint, 0f).Center;
}
