using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// COLLISIONINFO: the contact plane (and the last known one), the sliding and collision normals and what was
/// hit, as a transition builds them step by step. Normals are stored normalised, as retail does
/// (CTransition set_collision_normal / set_sliding_normal; ACE keeps them unnormalised, movement.md §5.3 #3).
/// </summary>
internal sealed class CollisionInfo
{
    public bool ContactPlaneValid;
    public Plane ContactPlane;
    public bool ContactPlaneCellKnown;
    public bool ContactPlaneIsWater;

    public bool LastKnownContactPlaneValid;
    public Plane LastKnownContactPlane;
    public bool LastKnownContactPlaneCellKnown;
    public bool LastKnownContactPlaneIsWater;

    public bool SlidingNormalValid;
    public Vector3 SlidingNormal;

    public bool CollisionNormalValid;
    public Vector3 CollisionNormal;

    public bool CollidedWithEnvironment;
    public bool HitObject;
    public int FramesStationaryFall;

    // COLLISIONINFO::set_contact_plane
    public void SetContactPlane(Plane plane, bool isWater)
    {
        ContactPlaneValid = true;
        ContactPlane = plane;
        ContactPlaneIsWater = isWater;
    }

    public void ClearContactPlane()
    {
        ContactPlaneValid = false;
        ContactPlaneIsWater = false;
    }

    // COLLISIONINFO::set_collision_normal
    public void SetCollisionNormal(Vector3 normal)
    {
        CollisionNormalValid = true;
        CollisionNormal = MoveMath.NormalizeCheckSmall(ref normal) ? Vector3.Zero : normal;
    }

    // COLLISIONINFO::set_sliding_normal: the horizontal part, normalised
    public void SetSlidingNormal(Vector3 normal)
    {
        SlidingNormalValid = true;
        var flat = new Vector3(normal.X, normal.Y, 0f);
        SlidingNormal = MoveMath.NormalizeCheckSmall(ref flat) ? Vector3.Zero : flat;
    }
}
