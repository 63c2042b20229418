using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// acshadow's movement reference: one mover walking against one placed object on a flat floor, frame by
/// frame, as the retail client moves it (CPhysicsObj::transition per quantum, CTransition within it). Each
/// frame's end is the last position plus velocity × quantum (plus gravity while not on walkable ground); the
/// state a frame leaves (contact plane, Contact, OnWalkable, sliding normal, stationary-fall count) is what
/// the next one starts from, as SetPositionInternal carries it. Deterministic: float32, fixed operation order.
/// </summary>
internal static class MovementReference
{
    public static IReadOnlyList<MovementFrame> Run(Mover mover, MovementObject? obstacle, Walk walk) =>
        Run(mover, obstacle is null ? [] : [obstacle], walk);

    /// <summary>
    /// The walk against several objects in one cell's shadow list, tested in list order with the first non-OK
    /// winning (CObjCell::find_obj_collisions): how the chart runs a model whose shapes are not one retail family.
    /// </summary>
    public static IReadOnlyList<MovementFrame> Run(Mover mover, IReadOnlyList<MovementObject> obstacles, Walk walk)
    {
        ArgumentNullException.ThrowIfNull(mover);
        ArgumentNullException.ThrowIfNull(obstacles);
        ArgumentNullException.ThrowIfNull(walk);
        var floor = new FlatFloor(walk.FloorZ);
        var collider = obstacles.Select(o => new ObjectCollider(o)).ToArray();
        var state = new CarriedState(walk.Start, walk.StartContact ?? floor.Plane);
        var frames = new List<MovementFrame>(walk.Frames);
        for (var f = 0; f < walk.Frames; f++)
            frames.Add(state.Advance(f, mover, walk, floor, collider));
        return frames;
    }

    /// <summary>What one frame hands the next (CPhysicsObj's position, TransientState, contact plane, sliding normal, velocity).</summary>
    private sealed class CarriedState(Vector3 position, Plane contactPlane)
    {
        private Vector3 _position = position;
        private bool _contact = true;
        private bool _onWalkable = ObjectInfo.IsValidWalkable(contactPlane.Normal);
        private Plane _contactPlane = contactPlane;
        private bool _contactIsWater;
        private Vector3? _sliding;
        private int _framesStationaryFall;
        private float _verticalVelocity;

        // CPhysicsObj::UpdatePhysicsInternal → transition → SetPositionInternal
        public MovementFrame Advance(int frame, Mover mover, Walk walk, FlatFloor floor, IReadOnlyList<ObjectCollider> collider)
        {
            var q = walk.Quantum;
            // calc_acceleration: no gravity while in contact with walkable ground
            var gravity = _contact && _onWalkable ? 0f : MovementConstants.Gravity;
            var velocity = new Vector3(walk.Velocity.X, walk.Velocity.Y, _verticalVelocity);
            var end = _position + MoveMath.Scale(velocity, q) + new Vector3(0f, 0f, 0.5f * gravity * q * q);
            _verticalVelocity += gravity * q;

            var transition = Begin(mover, velocity, floor, collider);
            transition.Path.InitPath(_position, end);
            var valid = transition.FindTransitionalPosition(out var steps);
            var collisions = transition.Collisions;
            if (valid)
            {
                _position = transition.Path.CurPos;
                _contact = collisions.ContactPlaneValid;
                if (_contact)
                {
                    _contactPlane = collisions.ContactPlane;
                    _contactIsWater = collisions.ContactPlaneIsWater;
                }
                _onWalkable = _contact && ObjectInfo.IsValidWalkable(_contactPlane.Normal);
                _sliding = collisions.SlidingNormalValid ? collisions.SlidingNormal : null;
                _framesStationaryFall = collisions.FramesStationaryFall;
                if (_onWalkable || transition.Info.VelocityStopped) _verticalVelocity = 0f;
            }
            else
            {
                // A failed transition leaves the object where it was and zeroes its cached velocity.
                _verticalVelocity = 0f;
            }
            return new MovementFrame(frame, valid, steps, _position, _contact, _onWalkable,
                _contact ? _contactPlane : null, _sliding,
                collisions.CollisionNormalValid ? collisions.CollisionNormal : null, collisions.HitObject)
            {
                Events = [.. transition.Trace.Events],
                MinMargin = transition.Trace.MinMargin,
            };
        }

        // CPhysicsObj::transition's set-up: get_object_info, init_sphere, the contact plane and sliding normal
        private Transition Begin(Mover mover, Vector3 velocity, FlatFloor floor, IReadOnlyList<ObjectCollider> collider)
        {
            var transition = new Transition(floor, collider);
            var info = transition.Info;
            info.EdgeSlide = mover.EdgeSlide;
            info.StepUpHeight = mover.StepUpHeight * mover.Scale;
            info.StepDownHeight = mover.StepDownHeight * mover.Scale;
            transition.Path.InitSphere(mover.Spheres, mover.Scale);
            if (_contact)
            {
                // CPhysicsObj::check_contact: moving away from the plane breaks contact
                if (MoveMath.Dot(velocity, _contactPlane.Normal) <= MovementConstants.Epsilon)
                {
                    info.Contact = true;
                    transition.InitContactPlane(_contactPlane, _contactIsWater);
                }
                else
                {
                    transition.InitLastKnownContactPlane(_contactPlane, _contactIsWater);
                }
            }
            info.OnWalkable = _onWalkable;
            if (_sliding is { } sliding) transition.InitSlidingNormal(sliding);
            transition.Collisions.FramesStationaryFall = _framesStationaryFall;
            return transition;
        }
    }
}
