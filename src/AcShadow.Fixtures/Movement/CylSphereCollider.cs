using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// CCylSphere::intersects_sphere for a moving mover: a vertical cylinder (world +Z axis whatever the object's
/// rotation) from its low point, tested against both spheres. In contact, sphere 0 steps up (or slides along
/// the radial normal when the top is out of step-up reach) and sphere 1 slides; airborne, sphere 0 lands and
/// sphere 1 collides; a step-down or a landing rests the sphere on the top.
/// </summary>
internal sealed class CylSphereCollider(Vector3 lowPoint, float radius, float height)
{
    // CCylSphere::intersects_sphere
    public TransitionState IntersectsSphere(Transition transition)
    {
        var path = transition.Path;
        var r0 = path.Radius(0);
        var disp0 = path.GlobalCenter[0] - lowPoint;
        var two = path.NumSphere > 1;
        var disp1 = two ? path.GlobalCenter[1] - lowPoint : Vector3.Zero;
        var radsum = radius - MovementConstants.Epsilon + r0;
        var hit0 = Collides(r0, disp0, radsum);
        var hit1 = two && Collides(path.Radius(1), disp1, radsum);

        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal || path.CheckWalkable)
            return hit0 || hit1 ? TransitionState.Collided : TransitionState.OK;
        if (path.StepDown) return hit0 || hit1 ? StepSphereDown(transition, disp0) : TransitionState.OK;
        if (!path.Collide)
        {
            var info = transition.Info;
            if (info.Contact || info.OnWalkable)
            {
                if (hit0) return StepSphereUp(transition, disp0, radsum);
                if (hit1) return SlideSphere(transition, disp1, radsum, 1);
                return TransitionState.OK;
            }
            if (hit0) return LandOnCylinder(transition, disp0, radsum);
            if (hit1) return CollideWithPoint(transition, disp1, radsum, 1);
            return TransitionState.OK;
        }
        if (!hit0 && !hit1) return TransitionState.OK;
        return LandOnTop(transition, disp0, radsum);
    }

    // CCylSphere::collides_with_sphere
    private bool Collides(float sphereRadius, Vector3 disp, float radsum)
    {
        if (!(MoveMath.LengthSquared2D(disp) <= radsum * radsum)) return false;
        var half = height * 0.5f;
        return sphereRadius - MovementConstants.Epsilon + half >= MathF.Abs(half - disp.Z);
    }

    /// <summary>
    /// CCylSphere::normal_of_collision: radial from where sphere i stood before the step when it was beside the
    /// cylinder then, else straight up or down. False when the contact is not definite.
    /// </summary>
    private bool NormalOfCollision(Transition transition, Vector3 checkDisp, float radsum, int sphere, out Vector3 normal)
    {
        var path = transition.Path;
        var disp = path.GlobalCurrCenter[sphere] - lowPoint;
        if (radsum * radsum < MoveMath.LengthSquared2D(disp))
        {
            normal = new Vector3(disp.X, disp.Y, 0f);
            var half = height * 0.5f;
            return path.Radius(sphere) - MovementConstants.Epsilon + half >= MathF.Abs(half - disp.Z)
                || MathF.Abs(disp.Z - checkDisp.Z) <= MovementConstants.Epsilon;
        }
        normal = new Vector3(0f, 0f, checkDisp.Z - disp.Z <= 0f ? 1f : -1f);
        return true;
    }

    // CCylSphere::step_sphere_up: too tall to step onto → slide round
    private TransitionState StepSphereUp(Transition transition, Vector3 disp, float radsum)
    {
        if (transition.Info.StepUpHeight < transition.Path.Radius(0) + height - disp.Z)
            return SlideSphere(transition, disp, radsum, 0);
        NormalOfCollision(transition, disp, radsum, 0, out var normal);
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        return transition.StepUp(normal) ? TransitionState.OK : transition.Path.StepUpSlide(transition);
    }

    // CCylSphere::slide_sphere
    private TransitionState SlideSphere(Transition transition, Vector3 disp, float radsum, int sphere)
    {
        NormalOfCollision(transition, disp, radsum, sphere, out var normal);
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        return SphereSlide.Slide(transition, normal, sphere);
    }

    // CCylSphere::step_sphere_down: rest sphere 0 on the top
    private TransitionState StepSphereDown(Transition transition, Vector3 disp0)
    {
        var path = transition.Path;
        var r0 = path.Radius(0);
        var stepScale = path.StepDownAmt * path.WalkInterp;
        if (MathF.Abs(stepScale) < MovementConstants.Epsilon) return TransitionState.Collided;
        var deltaZ = height + r0 - disp0.Z;
        var interp = (1f - deltaZ / stepScale) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < MovementConstants.PrimitiveInterpFloor) return TransitionState.Collided;
        var center = path.GlobalCenter[0];
        var contactZ = center.Z + (deltaZ - r0);
        // ACE passes is_water = true here ("is water?"); kept, so adjust_offset never lifts off a cylinder top.
        transition.Collisions.SetContactPlane(new Plane(Vector3.UnitZ, -contactZ), true);
        path.WalkInterp = interp;
        path.AddOffsetToCheckPos(new Vector3(0f, 0f, deltaZ));
        return TransitionState.Adjusted;
    }

    // CCylSphere::land_on_cylinder
    private TransitionState LandOnCylinder(Transition transition, Vector3 disp0, float radsum)
    {
        NormalOfCollision(transition, disp0, radsum, 0, out var normal);
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        transition.Path.SetCollide(normal);
        transition.Path.WalkableAllowance = MovementConstants.LandingZ;
        return TransitionState.Adjusted;
    }

    // CCylSphere::collide_with_point for a mover without PerfectClip: record the normal and stop
    private TransitionState CollideWithPoint(Transition transition, Vector3 disp, float radsum, int sphere)
    {
        NormalOfCollision(transition, disp, radsum, sphere, out var normal);
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.Collided;
        transition.Collisions.SetCollisionNormal(normal);
        return TransitionState.Collided;
    }

    /// <summary>The collide branch of CCylSphere::intersects_sphere: the airborne sphere lands on the top (time of impact on z).</summary>
    private TransitionState LandOnTop(Transition transition, Vector3 disp0, float radsum)
    {
        var path = transition.Path;
        var r0 = path.Radius(0);
        var movement = path.GlobalCurrCenter[0] - path.GlobalCenter[0];
        if (MathF.Abs(movement.Z) < MovementConstants.Epsilon) return TransitionState.Collided;
        var time = (height + r0 - disp0.Z) / movement.Z;
        var offset = MoveMath.Scale(movement, time);
        var reached = offset + disp0;
        if (radsum * radsum < MoveMath.LengthSquared2D(reached)) return TransitionState.OK;
        var interp = (1f - time) * path.WalkInterp;
        if (interp >= path.WalkInterp || interp < MovementConstants.PrimitiveInterpFloor) return TransitionState.Collided;
        var contactZ = path.GlobalCenter[0].Z + offset.Z - r0;
        transition.Collisions.SetContactPlane(new Plane(Vector3.UnitZ, -contactZ), true);
        transition.Collisions.ContactPlaneCellKnown = true;
        path.WalkInterp = interp;
        path.AddOffsetToCheckPos(offset);
        return TransitionState.Adjusted;
    }
}
