using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// Flat terrain at one height, everywhere under the walk: the land cell's triangle plane, made as the client
/// makes terrain planes (CPolygon::make_plane over a 24 m cell's triangle), and the terrain test every step
/// runs before any object (CLandCell::find_env_collisions → OBJECTINFO::validate_walkable). No water.
/// </summary>
internal sealed class FlatFloor
{
    private const float CellSize = 24f;

    public Plane Plane { get; }

    public FlatFloor(float z)
    {
        Plane = PolygonPlane.Compute([new Vector3(0f, 0f, z), new Vector3(CellSize, 0f, z), new Vector3(CellSize, CellSize, z)])!.Value;
    }

    // OBJECTINFO::validate_walkable (sphere 0's low point against the terrain plane)
    public TransitionState ValidateWalkable(Transition transition)
    {
        var path = transition.Path;
        var collisions = transition.Collisions;
        var info = transition.Info;
        var center = path.GlobalCenter[0];
        var radius = path.Radius(0);
        var low = center with { Z = center.Z - radius };
        var dist = MoveMath.Dot(low, Plane.Normal) + Plane.D;
        var mayStand = path.StepDown || !info.OnWalkable || ObjectInfo.IsValidWalkable(Plane.Normal);
        if (dist >= -MovementConstants.Epsilon)
        {
            if (dist > MovementConstants.Epsilon) return TransitionState.OK;
            if (mayStand) SetContact(collisions);
            if (!info.Contact && !path.StepDown)
            {
                collisions.SetCollisionNormal(Plane.Normal);
                collisions.CollidedWithEnvironment = true;
            }
            return TransitionState.OK;
        }
        if (path.CheckWalkable) return TransitionState.Collided;
        var zDist = dist / Plane.Normal.Z;
        if (mayStand)
        {
            SetContact(collisions);
            if (path.StepDown)
            {
                var interp = (1f - -1f / (path.StepDownAmt * path.WalkInterp) * zDist) * path.WalkInterp;
                if (interp >= path.WalkInterp || interp < MovementConstants.PrimitiveInterpFloor) return TransitionState.Collided;
                path.WalkInterp = interp;
            }
            path.AddOffsetToCheckPos(new Vector3(0f, 0f, -zDist));
            if (!info.Contact && !path.StepDown)
            {
                collisions.SetCollisionNormal(Plane.Normal);
                collisions.CollidedWithEnvironment = true;
            }
            return TransitionState.Adjusted;
        }
        // Retail returns OK when the plane may not be stood on (ACE: Adjusted, movement.md §5.3 #6).
        return TransitionState.OK;
    }

    private void SetContact(CollisionInfo collisions)
    {
        collisions.SetContactPlane(Plane, false);
        collisions.ContactPlaneCellKnown = true;
    }
}
