using System.Numerics;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// CSphere::slide_sphere, the core of every slide: the whole step g (check centre − current centre) is
/// replaced by its projection on the line where the hit surface meets the contact plane. A projection
/// shorter than √ε stops the step (Collided): that is what a flat face met head-on does.
/// </summary>
internal static class SphereSlide
{
    // CSphere::slide_sphere (global sphere i against collision normal n)
    public static TransitionState Slide(Transition transition, Vector3 normal, int sphere = 0)
    {
        var path = transition.Path;
        var collisions = transition.Collisions;
        var center = path.GlobalCenter[sphere];
        var currCenter = path.GlobalCurrCenter[sphere];
        if (normal == Vector3.Zero)
        {
            path.AddOffsetToCheckPos(MoveMath.Scale(currCenter - center, 0.5f));
            return TransitionState.Adjusted;
        }
        collisions.SetCollisionNormal(normal);
        var g = center - currCenter;
        var plane = collisions.ContactPlaneValid ? collisions.ContactPlane : collisions.LastKnownContactPlane;
        var direction = Vec.Cross(normal, plane.Normal);
        var directionSquared = MoveMath.LengthSquared(direction);
        var trace = transition.Trace;
        trace.Margin(directionSquared - MovementConstants.Epsilon);
        if (directionSquared >= MovementConstants.Epsilon)
        {
            var along = MoveMath.Dot(direction, g);
            var offset = MoveMath.Scale(direction, along * (1f / directionSquared));
            var offsetSquared = MoveMath.LengthSquared(offset);
            // A head-on hit has no tangential part at all: that is no threshold decision, so no margin.
            if (offsetSquared > 0f) trace.Margin(offsetSquared - MovementConstants.Epsilon);
            if (offsetSquared < MovementConstants.Epsilon)
            {
                trace.Event("slideStopped");
                return TransitionState.Collided;
            }
            path.AddOffsetToCheckPos(offset - g);
            trace.Event("slide");
            return TransitionState.Slid;
        }
        if (MoveMath.Dot(normal, plane.Normal) >= 0f)
        {
            path.AddOffsetToCheckPos(MoveMath.Scale(normal, -MoveMath.Dot(normal, g)));
            trace.Event("slide");
            return TransitionState.Slid;
        }
        // Retail returns Collided here; ACE returns OK (movement.md §5.3 #2).
        trace.Event("slideStopped");
        return TransitionState.Collided;
    }
}
