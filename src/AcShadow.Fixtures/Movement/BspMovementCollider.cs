using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// One BSP part against the moving spheres: CPhysicsPart::find_obj_collisions (spheres into part space),
/// CGfxObj::find_obj_collisions (broad phase on the root sphere) and BSPTREE::find_collisions with its
/// branches: placement, check walkable, step down, landing (collide), in contact, airborne.
/// </summary>
internal sealed class BspMovementCollider(BspPart part)
{
    private readonly BspMovementTraversal _tree = new(part.Bsp);
    private readonly ClientFrameMatrix _matrix = part.Pose.Matrix;
    private float Scale => part.Pose.Scale;

    // CPhysicsPart::find_obj_collisions → CGfxObj::find_obj_collisions
    public TransitionState FindCollisions(Transition transition)
    {
        if (_tree.IsEmpty) return TransitionState.OK;
        var path = transition.Path;
        path.CacheLocalSpaceSphere(part.Pose, _matrix);
        for (var i = 0; i < path.NumSphere; i++)
        {
            var sphere = path.LocalSpaceSphere[i];
            if (SphereBounds.BroadPhaseHits(_tree.Root, sphere.Center, sphere.Radius)) return FindBspCollisions(transition);
        }
        return TransitionState.OK;
    }

    // BSPTREE::find_collisions
    private TransitionState FindBspCollisions(Transition transition)
    {
        var path = transition.Path;
        var collisions = transition.Collisions;
        var sphere0 = path.LocalSpaceSphere[0];
        var twoSpheres = path.NumSphere > 1;
        var sphere1 = twoSpheres ? path.LocalSpaceSphere[1] : default;
        var movement = sphere0.Center - path.LocalSpaceCurrCenter[0];

        if (path.InsertType == InsertType.Placement || path.ObstructionEthereal)
        {
            var blocked = part.Solid.Overlaps(sphere0.Center, sphere0.Radius) || (twoSpheres && part.Solid.Overlaps(sphere1.Center, sphere1.Radius));
            return blocked ? TransitionState.Collided : TransitionState.OK;
        }
        if (path.CheckWalkable)
            return _tree.HitsWalkable(path.WalkableAllowance, sphere0.Center, sphere0.Radius, path.LocalSpaceZ) ? TransitionState.Collided : TransitionState.OK;
        if (path.StepDown) return StepSphereDown(transition, sphere0);

        if (path.Collide)
        {
            return RestOnWalkable(transition, sphere0, movement);
        }

        CompiledPolygon? touched0 = null;
        if (transition.Info.Contact)
        {
            var hit0 = _tree.SphereIntersectsPoly(sphere0.Center, sphere0.Radius, movement, ref touched0);
            TouchMargin(transition, touched0, sphere0);
            if (hit0) return StepSphereUp(transition, touched0!.Normal);
            if (twoSpheres)
            {
                CompiledPolygon? touched1 = null;
                var hit1 = _tree.SphereIntersectsPoly(sphere1.Center, sphere1.Radius, movement, ref touched1);
                TouchMargin(transition, touched1, sphere1);
                if (hit1) return SphereSlide.Slide(transition, ToGlobal(touched1!.Normal));
                if (touched1 is not null) return NegPolyHit(path, touched1, false);
                if (touched0 is not null) return NegPolyHit(path, touched0, true);
            }
            return TransitionState.OK;
        }

        if (_tree.SphereIntersectsPoly(sphere0.Center, sphere0.Radius, movement, ref touched0) || touched0 is not null)
        {
            path.WalkableAllowance = MovementConstants.LandingZ;
            path.SetCollide(ToGlobal(touched0!.Normal));
            return TransitionState.Adjusted;
        }
        if (twoSpheres)
        {
            CompiledPolygon? touched1 = null;
            if (_tree.SphereIntersectsPoly(sphere1.Center, sphere1.Radius, movement, ref touched1) || touched1 is not null)
            {
                collisions.SetCollisionNormal(ToGlobal(touched1!.Normal));
                return TransitionState.Collided;
            }
        }
        return TransitionState.OK;
    }

    /// <summary>How far the touched polygon's plane is from the reach it was touched within (|dist| against r − ε).</summary>
    private static void TouchMargin(Transition transition, CompiledPolygon? touched, Sphere sphere)
    {
        if (touched is null) return;
        transition.Trace.Margin(MathF.Abs(touched.Distance(sphere.Center)) - (sphere.Radius - MovementConstants.Epsilon));
    }

    // BSPTREE::step_sphere_down
    private TransitionState StepSphereDown(Transition transition, Sphere sphere0)
    {
        var path = transition.Path;
        var amount = -(path.StepDownAmt * path.WalkInterp);
        var movement = MoveMath.Scale(MoveMath.Scale(path.LocalSpaceZ, amount), 1f / Scale);
        return RestOnWalkable(transition, sphere0, movement);
    }

    /// <summary>
    /// find_walkable along <paramref name="movement"/>; if a walkable polygon lifted the sphere, the check position
    /// moves with it (× scale), the contact plane becomes that polygon's and the path remembers it (Adjusted).
    /// </summary>
    private TransitionState RestOnWalkable(Transition transition, Sphere sphere0, Vector3 movement)
    {
        var path = transition.Path;
        var center = sphere0.Center;
        var walkable = _tree.FindWalkable(path, ref center, sphere0.Radius, movement, path.LocalSpaceZ);
        if (walkable is null) return TransitionState.OK;
        path.AddOffsetToCheckPos(ToGlobalOffset(center - sphere0.Center));
        StandOn(transition, walkable, center, sphere0.Radius);
        return TransitionState.Adjusted;
    }

    // BSPTREE::step_sphere_up
    private TransitionState StepSphereUp(Transition transition, Vector3 localNormal) =>
        transition.StepUp(ToGlobal(localNormal)) ? TransitionState.OK : transition.Path.StepUpSlide(transition);

    // BSPTREE::neg_poly_hit
    private TransitionState NegPolyHit(SpherePath path, CompiledPolygon polygon, bool stepUp)
    {
        path.SetNegPolyHit(stepUp, ToGlobal(polygon.Normal));
        return TransitionState.OK;
    }

    /// <summary>The contact plane becomes the walkable polygon's plane in world space; the path remembers the walkable.</summary>
    private void StandOn(Transition transition, CompiledPolygon walkable, Vector3 localCenter, float localRadius)
    {
        var collisions = transition.Collisions;
        var normal = ToGlobal(walkable.Normal);
        var point = part.Pose.ToEntity(MoveMath.Scale(walkable.Normal, -walkable.D));
        collisions.SetContactPlane(new Plane(normal, -MoveMath.Dot(normal, point)), false);
        collisions.ContactPlaneCellKnown = true;
        var path = transition.Path;
        path.Walkable = new WalkableSurface(walkable, part.Pose, localCenter, localRadius, path.LocalSpaceZ);
    }

    // Frame::localtoglobalvec by the part frame's matrix (path->localspace_pos).
    private Vector3 ToGlobal(Vector3 localVector) => _matrix.LocalToGlobalVec(localVector);

    private Vector3 ToGlobalOffset(Vector3 localOffset) => MoveMath.Scale(ToGlobal(localOffset), Scale);
}
