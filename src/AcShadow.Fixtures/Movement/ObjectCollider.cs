using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// CPhysicsObj::FindObjCollisions for the one object: its family (BSP parts in Setup order, else
/// CylSpheres, else Spheres; the first non-OK wins) and what an ethereal object does with a hit (nothing:
/// ts OK, the collision normal dropped). Shapes are posed in the world once, from the object's frame and scale.
/// </summary>
internal sealed class ObjectCollider
{
    private readonly BspMovementCollider[] _parts;
    private readonly CylSphereCollider[] _cylinders;
    private readonly SphereCollider[] _spheres;
    private readonly bool _ethereal;

    public ObjectCollider(MovementObject obstacle)
    {
        _ethereal = obstacle.Ethereal;
        var scale = obstacle.Scale;
        var parts = new List<BspMovementCollider>();
        var cylinders = new List<CylSphereCollider>();
        var spheres = new List<SphereCollider>();
        var placed = new Frame(obstacle.Position, ClientFrameMatrix.PlacedRotation(obstacle.Rotation));
        var frame = ClientFrameMatrix.From(placed);
        foreach (var shape in obstacle.Shapes)
        {
            var position = frame.LocalToGlobal(MoveMath.Scale(shape.LocalPosition, scale));
            switch (shape.CollisionType)
            {
                case CollisionType.Bsp when shape.GfxObjId is { } id && obstacle.Bsps.TryGetValue(id, out var bsp):
                    // CPartArray::UpdateParts: Frame::combine(object frame, part frame, scale), its rotation through Frame::set_rotate.
                    var part = ClientFrameMatrix.Combine(placed, new Frame(shape.LocalPosition, shape.LocalRotation), scale);
                    var pose = new PartPose(part.Position, part.Rotation, shape.Scale * scale);
                    parts.Add(new BspMovementCollider(new BspPart(pose, bsp)));
                    break;
                case CollisionType.Cylinder:
                    cylinders.Add(new CylSphereCollider(position, shape.Radius * scale, shape.CylHeight * scale));
                    break;
                case CollisionType.Sphere:
                    spheres.Add(new SphereCollider(position, shape.Radius * scale));
                    break;
            }
        }
        _parts = [.. parts];
        _cylinders = [.. cylinders];
        _spheres = [.. spheres];
    }

    // CPhysicsObj::FindObjCollisions
    public TransitionState FindObjCollisions(Transition transition)
    {
        var path = transition.Path;
        if (_ethereal && path.StepDown) return TransitionState.OK;
        path.ObstructionEthereal = _ethereal;
        var state = TransitionState.OK;
        if (_parts.Length > 0)
        {
            foreach (var part in _parts)
                if ((state = part.FindCollisions(transition)) != TransitionState.OK) break;
        }
        else if (_cylinders.Length > 0)
        {
            foreach (var cylinder in _cylinders)
                if ((state = cylinder.IntersectsSphere(transition)) != TransitionState.OK) break;
        }
        else
        {
            foreach (var sphere in _spheres)
                if ((state = sphere.IntersectsSphere(transition)) != TransitionState.OK) break;
        }
        if (state != TransitionState.OK) state = FindObjCollisionsInner(transition, state);
        path.ObstructionEthereal = false;
        return state;
    }

    // CPhysicsObj::FindObjCollisions_Inner (a dynamic object: never Static)
    private TransitionState FindObjCollisionsInner(Transition transition, TransitionState state)
    {
        if (transition.Path.StepDown) return state;
        transition.Collisions.HitObject = true;
        if (!_ethereal) return state;
        transition.Collisions.CollisionNormalValid = false;
        return TransitionState.OK;
    }
}
