using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// CSphere::intersects_sphere for a moving mover against a Setup sphere (not a creature): in contact, sphere 0
/// steps up (or slides away from the centre when the top is out of step-up reach) and sphere 1 slides;
/// airborne, sphere 0 lands and sphere 1 collides; a step-down rests sphere 0 on the sphere's top when the
/// resting normal is walkable.
/// </summary>
internal sealed class SphereCollider(Vector3 center, float radius)
{
    // CSphere::intersects_sphere
    public TransitionState IntersectsSphere(Transition transition)
    {
        var path = transition.Path;
        var disp0 = path.GlobalCenter[0] - center;
        var two = path.NumSphere > 1;
        var disp1 = two ? path.GlobalCenter[1] - center : Vector3.Zero;
        var radsum = path.Radius(0) + radius - MovementConstants.Epsilon;
        var hit0 = MoveMath.LengthSquared(disp0) <= radsum * radsum;
        var hit1 = two && MoveMath.LengthSquared(disp1) <= radsum * radsum;

        if (path.ObstructionEthereal || path.InsertType == InsertType.Placement || path.CheckWalkable)
            return hit0 || hit1 ? TransitionState.Collided : TransitionState.OK;
        if (path.StepDown) return hit0 || hit1 ? StepSphereDown(transition, disp0, radsum) : TransitionState.OK;
        if (!path.Collide)
        {
            var info = transition.Info;
            if (info.Contact || info.OnWalkable)
            {
                if (hit0) return StepSphereUp(transition, disp0, radsum);
                if (hit1) return SlideSphere(transition, 1);
                return TransitionState.OK;
            }
            if (hit0) return LandOnSphere(transition);
            if (hit1) return CollideWithPoint(transition, 1);
            return TransitionState.OK;
        }
        if (!hit0 && !hit1) return TransitionState.OK;
        return LandOnTop(transition, disp0, radsum);
    }

    // CSphere::step_sphere_up
    private TransitionState StepSphereUp(Transition transition, Vector3 disp0, float radsum)
    {
        if (transition.Info.StepUpHeight < radsum + MovementConstants.Epsilon - disp0.Z) return SlideSphere(transition, 0);
        var normal = transition.Path.GlobalCurrCenter[0] - center;
        return transition.StepUp(normal) ? TransitionState.OK : transition.Path.StepUpSlide(transition);
    }

    // CSphere::slide_sphere (the wrapper): away from the centre, from where sphere i stood
    private TransitionState SlideSphere(Transition transition, int sphere)
    {
        var normal = transition.Path.GlobalCurrCenter[sphere] - center;
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        return SphereSlide.Slide(transition, normal, sphere);
    }

    // CSphere::land_on_sphere
    private TransitionState LandOnSphere(Transition transition)
    {
        var normal = transition.Path.GlobalCurrCenter[0] - center;
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        transition.Path.SetCollide(normal);
        transition.Path.WalkableAllowance = MovementConstants.LandingZ;
        return TransitionState.Adjusted;
    }

    // CSphere::collide_with_point for a mover without PerfectClip
    private TransitionState CollideWithPoint(Transition transition, int sphere)
    {
        var normal = transition.Path.GlobalCurrCenter[sphere] - center;
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        transition.Collisions.SetCollisionNormal(normal);
        return TransitionState.Collided;
    }

    // CSphere::step_sphere_down: rest sphere 0 on the sphere where the resting normal is walkable
    private TransitionState StepSphereDown(Transition transition, Vector3 disp0, float radsum)
    {
        var path = transition.Path;
        var stepDown = path.StepDownAmt * path.WalkInterp;
        if (MathF.Abs(stepDown) < MovementConstants.Epsilon) return TransitionState.Collided;
        radsum += MovementConstants.Epsilon;
        var rise = MathF.Sqrt(radsum * radsum - MoveMath.LengthSquared2D(disp0));
        var scaledStep = (rise - disp0.Z) / stepDown;
        var interp = (1f - scaledStep) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < MovementConstants.PrimitiveInterpFloor) return TransitionState.Collided;
        var lift = stepDown * scaledStep;
        var normal = MoveMath.Scale(new Vector3(disp0.X, disp0.Y, disp0.Z + lift), 1f / radsum);
        if (normal.Z <= path.WalkableAllowance) return TransitionState.OK;
        var point = MoveMath.Scale(normal, radius) + center;
        transition.Collisions.SetContactPlane(new Plane(normal, -MoveMath.Dot(normal, point)), true);
        transition.Collisions.ContactPlaneCellKnown = true;
        path.WalkInterp = interp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, lift));
        return TransitionState.Adjusted;
    }

    /// <summary>The collide branch of CSphere::intersects_sphere: the airborne sphere lands where it first touches, if walkable.</summary>
    private TransitionState LandOnTop(Transition transition, Vector3 disp0, float radsum)
    {
        var path = transition.Path;
        var movement = path.GlobalCurrCenter[0] - path.GlobalCenter[0];
        radsum += MovementConstants.Epsilon;
        var lengthSquared = MoveMath.LengthSquared(movement);
        if (MathF.Abs(lengthSquared) < MovementConstants.Epsilon) return TransitionState.Collided;
        var diff = -MoveMath.Dot(movement, disp0);
        var t = MathF.Sqrt(diff * diff - (MoveMath.LengthSquared(disp0) - radsum * radsum) * lengthSquared) + diff;
        if (t > 1f) t = diff * 2f - t;
        var time = t / lengthSquared;
        var interp = (1f - time) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < MovementConstants.PrimitiveInterpFloor) return TransitionState.Collided;
        var moved = MoveMath.Scale(movement, time);
        var normal = MoveMath.Scale(disp0 + moved, 1f / radsum);
        if (!(normal.Z > path.WalkableAllowance)) return TransitionState.OK;
        var point = path.GlobalCenter[0] - MoveMath.Scale(normal, path.Radius(0));
        transition.Collisions.SetContactPlane(new Plane(normal, -MoveMath.Dot(normal, point)), true);
        transition.Collisions.ContactPlaneCellKnown = true;
        path.WalkInterp = interp;
        path.AddOffsetToCheckPos(moved);
        return TransitionState.Adjusted;
    }
}
