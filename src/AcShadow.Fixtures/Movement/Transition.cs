using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// CTransition for one mover in one land cell holding a flat floor and its shadow objects (usually one): the
/// movement is cut into steps, each step's offset adjusted to the contact plane and sliding normal, inserted
/// (floor first, then the objects in order), responded to (step up, step down, slide, edge slide, land) and validated.
/// </summary>
internal sealed class Transition(FlatFloor floor, IReadOnlyList<ObjectCollider> obstacles)
{
    public SpherePath Path { get; } = new();
    public CollisionInfo Collisions { get; } = new();
    public ObjectInfo Info { get; } = new();
    public MovementTrace Trace { get; } = new();

    // CTransition::init_contact_plane
    public void InitContactPlane(Plane plane, bool isWater)
    {
        InitLastKnownContactPlane(plane, isWater);
        Collisions.SetContactPlane(plane, isWater);
        Collisions.ContactPlaneCellKnown = true;
    }

    // CTransition::init_last_known_contact_plane
    public void InitLastKnownContactPlane(Plane plane, bool isWater)
    {
        Collisions.LastKnownContactPlaneValid = true;
        Collisions.LastKnownContactPlane = plane;
        Collisions.LastKnownContactPlaneIsWater = isWater;
        Collisions.LastKnownContactPlaneCellKnown = true;
    }

    // CTransition::init_sliding_normal
    public void InitSlidingNormal(Vector3 normal)
    {
        Collisions.SlidingNormalValid = true;
        Collisions.SlidingNormal = MoveMath.NormalizeCheckSmall(ref normal) ? Vector3.Zero : normal;
    }

    // CTransition::calc_num_steps (a non-viewer)
    public static (int Steps, Vector3 PerStep) CalcNumSteps(Vector3 offset, float radius)
    {
        var dist = MathF.Sqrt(MoveMath.LengthSquared(offset));
        var ratio = dist / radius;
        if (ratio > 1f)
        {
            var steps = (int)MathF.Ceiling(ratio);
            return (steps, MoveMath.Scale(offset, 1f / steps));
        }
        return offset == Vector3.Zero ? (0, Vector3.Zero) : (1, offset);
    }

    // CTransition::find_transitional_position (heading fixed, so no per-step rotation)
    public bool FindTransitionalPosition(out int steps)
    {
        var offset0 = Path.EndPos - Path.BeginPos;
        var (numSteps, perStep) = CalcNumSteps(offset0, Path.Radius(0));
        steps = numSteps;
        // ceil(|offset| / r) flips at whole numbers of radii (and at one radius for a single step)
        var ratio = MathF.Sqrt(MoveMath.LengthSquared(offset0)) / Path.Radius(0);
        Trace.Margin((ratio - MathF.Max(1f, MathF.Round(ratio))) * Path.Radius(0));
        Path.SetCheckPos(Path.CurPos);
        if (numSteps == 0) return true;
        var state = TransitionState.OK;
        for (var step = 0; step < numSteps; step++)
        {
            var offset = AdjustOffset(perStep);
            if (MoveMath.LengthSquared(offset) < MovementConstants.EpsilonSquared)
                return step != 0 && state == TransitionState.OK;
            Collisions.SlidingNormalValid = false;
            Collisions.ClearContactPlane();
            Path.AddOffsetToCheckPos(offset);
            state = ValidateTransition(TransitionalInsert(3));
            if (Collisions.FramesStationaryFall > 0) break;
        }
        return state == TransitionState.OK;
    }

    // CTransition::adjust_offset
    public Vector3 AdjustOffset(Vector3 offset)
    {
        var collisions = Collisions;
        var slidingAngle = MoveMath.Dot(offset, collisions.SlidingNormal);
        var slide = false;
        if (collisions.SlidingNormalValid)
        {
            if (slidingAngle < 0f) slide = true;
            else collisions.SlidingNormalValid = false;
        }
        if (!collisions.ContactPlaneValid)
            return slide ? offset - MoveMath.Scale(collisions.SlidingNormal, slidingAngle) : offset;

        var normal = collisions.ContactPlane.Normal;
        var contactAngle = MoveMath.Dot(offset, normal);
        if (slide)
        {
            var along = Vec3Cross(normal, collisions.SlidingNormal);
            offset = MoveMath.NormalizeCheckSmall(ref along) ? Vector3.Zero : MoveMath.Scale(along, MoveMath.Dot(along, offset));
        }
        else if (contactAngle <= 0f)
        {
            offset -= MoveMath.Scale(normal, contactAngle);
        }
        else if (MathF.Abs(normal.Z) > MovementConstants.Epsilon)
        {
            // Plane::snap_to_plane: z follows the plane under the horizontal offset
            offset.Z = -(offset.X * normal.X + offset.Y * normal.Y) / normal.Z;
        }

        if (!collisions.ContactPlaneCellKnown || collisions.ContactPlaneIsWater) return offset;
        var center = Path.GlobalCenter[0];
        var radius = Path.Radius(0);
        var dist = MoveMath.Dot(center, normal) + collisions.ContactPlane.D;
        if (dist >= radius - MovementConstants.Epsilon) return offset;
        var zDist = (radius - dist) / normal.Z;
        if (radius > MathF.Abs(zDist)) Path.AddOffsetToCheckPos(new Vector3(0f, 0f, zDist));
        return offset;
    }

    private static Vector3 Vec3Cross(Vector3 a, Vector3 b) => Collision.Vec.Cross(a, b);

    // CTransition::insert_into_cell: the land cell's floor, then its object
    private TransitionState InsertIntoCell(int attempts)
    {
        var state = TransitionState.OK;
        for (var i = 0; i < attempts; i++)
        {
            state = FindCollisions();
            switch (state)
            {
                case TransitionState.OK:
                case TransitionState.Collided:
                    return state;
                case TransitionState.Slid:
                    Collisions.ClearContactPlane();
                    break;
            }
        }
        return state;
    }

    // CLandCell::find_collisions: terrain first, then CObjCell::find_obj_collisions over the shadow objects
    // in list order, the first non-OK winning (retail iterates forward; ACE reverses, movement.md §5.3 #1)
    private TransitionState FindCollisions()
    {
        var state = floor.ValidateWalkable(this);
        for (var i = 0; i < obstacles.Count && state == TransitionState.OK; i++)
            state = obstacles[i].FindObjCollisions(this);
        return state;
    }

    // CTransition::transitional_insert
    public TransitionState TransitionalInsert(int attempts)
    {
        if (attempts <= 0) return TransitionState.Invalid;
        var state = TransitionState.Invalid;
        for (var i = 0; i < attempts; i++)
        {
            state = InsertIntoCell(attempts);
            switch (state)
            {
                case TransitionState.OK:
                    break;
                case TransitionState.Collided:
                    Path.NegPolyHit = false;
                    return state;
                case TransitionState.Adjusted:
                    Path.NegPolyHit = false;
                    break;
                case TransitionState.Slid:
                    Collisions.ClearContactPlane();
                    Path.NegPolyHit = false;
                    break;
            }
            if (state != TransitionState.OK) continue;

            if (Path.Collide) return Land(attempts);

            if (Path.NegPolyHit && !Path.StepDown && !Path.StepUp)
            {
                Path.NegPolyHit = false;
                if (Path.NegStepUp)
                {
                    if (!StepUp(Path.NegCollisionNormal)) state = Path.StepUpSlide(this);
                }
                else
                {
                    state = SphereSlide.Slide(this, Path.NegCollisionNormal);
                }
                continue;
            }

            if (Collisions.ContactPlaneValid || !Info.Contact || Path.StepDown) return TransitionState.OK;

            if (KeepOnGround(ref state)) return state;
        }
        return state;
    }

    /// <summary>
    /// The grounded mover found no contact plane this step: step it down onto the ground (step-down height on
    /// walkable ground, else 0.04), in two halves when that is more than the sphere's diameter; failing that,
    /// edge-slide. True when the insert is over with <paramref name="state"/>.
    /// </summary>
    private bool KeepOnGround(ref TransitionState state)
    {
        var (height, z) = PrepareStep(Info.StepDownHeight);
        var diameter = Path.Radius(0) * 2f;
        if (Path.NumSphere < 2 && diameter < height) height = Path.Radius(0) * 0.5f;
        if (diameter >= height)
        {
            if (StepDown(height, z))
            {
                Path.Walkable = null;
                Trace.Event("stepDown");
                state = TransitionState.OK;
                return true;
            }
        }
        else
        {
            height *= 0.5f;
            if (StepDown(height, z) || StepDown(height, z))
            {
                Path.Walkable = null;
                Trace.Event("stepDown");
                state = TransitionState.OK;
                return true;
            }
        }
        return EdgeSlide(ref state, height, z);
    }

    /// <summary>
    /// transitional_insert's landing: an airborne step hit something (set_collide). It stands if what it rests
    /// on is walkable for landing and a placement insert confirms it; otherwise the step is undone.
    /// </summary>
    private TransitionState Land(int attempts)
    {
        Path.Collide = false;
        var reset = true;
        var state = TransitionState.OK;
        if (Collisions.ContactPlaneValid && CheckWalkable(MovementConstants.LandingZ))
        {
            Path.Backup = Path.InsertType;
            Path.InsertType = InsertType.Placement;
            state = TransitionalInsert(attempts);
            Path.InsertType = Path.Backup;
            reset = state != TransitionState.OK;
        }
        Path.Walkable = null;
        Trace.Event(reset ? "landFailed" : "land");
        if (!reset) return state;
        Path.RestoreCheckPos();
        Collisions.ClearContactPlane();
        if (Collisions.LastKnownContactPlaneValid)
        {
            Collisions.LastKnownContactPlaneValid = false;
            Info.VelocityStopped = true;
        }
        else
        {
            Collisions.SetCollisionNormal(Path.StepUpNormal);
        }
        return TransitionState.Collided;
    }

    /// <summary>
    /// How far a step up or down may go and what it may stand on: the mover's own height and floor_z on walkable
    /// ground, else 0.04 m and z_for_landing. Sets walkable_allowance and saves the check position.
    /// </summary>
    private (float Height, float Z) PrepareStep(float walkableHeight)
    {
        var (height, z) = Info.OnWalkable ? (walkableHeight, MovementConstants.FloorZ) : (MovementConstants.OffWalkableStep, MovementConstants.LandingZ);
        Path.WalkableAllowance = z;
        Path.SaveCheckPos();
        return (height, z);
    }

    // CTransition::step_down
    public bool StepDown(float height, float z)
    {
        Path.NegPolyHit = false;
        Path.StepDown = true;
        Path.StepDownAmt = height;
        Path.WalkInterp = 1f;
        if (!Path.StepUp) Path.AddOffsetToCheckPos(new Vector3(0f, 0f, -height));
        var state = TransitionalInsert(5);
        Path.StepDown = false;
        if (state != TransitionState.OK || !Collisions.ContactPlaneValid || Collisions.ContactPlane.Normal.Z < z) return false;
        if (Info.EdgeSlide && !Path.StepUp && !CheckWalkable(z)) return false;
        Path.Backup = Path.InsertType;
        Path.InsertType = InsertType.Placement;
        state = TransitionalInsert(1);
        Path.InsertType = Path.Backup;
        return state == TransitionState.OK;
    }

    // CTransition::step_up
    public bool StepUp(Vector3 normal)
    {
        Collisions.ClearContactPlane();
        Path.StepUp = true;
        Path.StepUpNormal = normal;
        var (height, z) = PrepareStep(Info.StepUpHeight);
        var stepped = StepDown(height, z);
        Path.StepUp = false;
        Path.Walkable = null;
        Trace.Event(stepped ? "stepUp" : "stepUpFailed");
        if (!stepped) Path.RestoreCheckPos();
        return stepped;
    }

    /// <summary>
    /// CTransition::check_walkable: true when the remembered walkable is still under half the sphere, or when
    /// a probe down by the step-down height (halved as in transitional_insert) finds walkable ground.
    /// </summary>
    public bool CheckWalkable(float z)
    {
        if (!Info.OnWalkable || Path.CheckWalkables()) return true;
        var backup = Path.CheckPos;
        var height = Info.StepDownHeight;
        Path.WalkableAllowance = z;
        Path.CheckWalkable = true;
        var radius = Path.Radius(0);
        if (Path.NumSphere < 2 && height > radius * 2f) height = radius * 0.5f;
        if (height > radius * 2f) height *= 0.5f;
        Path.AddOffsetToCheckPos(new Vector3(0f, 0f, -height));
        var state = TransitionalInsert(1);
        Path.CheckWalkable = false;
        Path.SetCheckPos(backup);
        return state != TransitionState.OK;
    }

    /// <summary>
    /// CTransition::edge_slide: a grounded mover found no floor within step-down height. Without OnWalkable and
    /// EdgeSlide it walks off (true, OK, no contact plane). Otherwise a steep contact plane cliff-slides, a
    /// remembered walkable precipice-slides along its crossed edge, and with neither it looks for the
    /// walkable from where the step began. Retail restores the check position before sliding (ACE slides
    /// first and loses the slide: movement.md §5.3 #4).
    /// </summary>
    private bool EdgeSlide(ref TransitionState state, float height, float z)
    {
        if (!Info.OnWalkable || !Info.EdgeSlide)
        {
            Trace.Event("walkOff");
            Path.Walkable = null;
            RestoreAndClear();
            state = TransitionState.OK;
            return true;
        }
        if (Collisions.ContactPlaneValid && Collisions.ContactPlane.Normal.Z < z)
        {
            var contact = Collisions.ContactPlane;
            Trace.Event("cliffSlide");
            Path.Walkable = null;
            RestoreAndClear();
            state = CliffSlide(contact);
            return false;
        }
        if (Path.Walkable is not null)
        {
            Trace.Event("precipiceSlide");
            RestoreAndClear();
            state = Path.PrecipiceSlide(this);
            return state == TransitionState.Collided;
        }
        if (Collisions.ContactPlaneValid)
        {
            Path.Walkable = null;
            RestoreAndClear();
            state = TransitionState.OK;
            return true;
        }
        Path.AddOffsetToCheckPos(Path.GlobalCurrCenter[0] - Path.GlobalCenter[0]);
        StepDown(height, z);
        Collisions.ClearContactPlane();
        Path.RestoreCheckPos();
        if (Path.Walkable is { } walkable)
        {
            // The walkable's sphere is taken again at the restored position, in the walkable's part space.
            var (center, radius) = walkable.Pose.ToLocal(Path.GlobalCenter[0], Path.Radius(0));
            walkable.Center = center;
            walkable.Radius = radius;
            Trace.Event("precipiceSlide");
            state = Path.PrecipiceSlide(this);
            return state == TransitionState.Collided;
        }
        Trace.Event("edgeStop");
        state = TransitionState.Collided;
        return true;
    }

    private void RestoreAndClear()
    {
        Path.RestoreCheckPos();
        Collisions.ClearContactPlane();
    }

    // CTransition::cliff_slide: slide along the line where the steep plane meets the last known one
    private TransitionState CliffSlide(Plane contact)
    {
        var line = Collision.Vec.Cross(contact.Normal, Collisions.LastKnownContactPlane.Normal);
        line.Z = 0f;
        var normal = new Vector3(line.Z - line.Y, line.X - line.Z, 0f);
        if (MoveMath.NormalizeCheckSmall(ref normal)) return TransitionState.OK;
        var offset = Path.GlobalCenter[0] - Path.GlobalCurrCenter[0];
        var angle = MoveMath.Dot(normal, offset);
        if (angle <= 0f)
        {
            Path.AddOffsetToCheckPos(MoveMath.Scale(normal, angle));
            Collisions.SetCollisionNormal(normal);
        }
        else
        {
            Path.AddOffsetToCheckPos(MoveMath.Scale(normal, -angle));
            Collisions.SetCollisionNormal(-normal);
        }
        return TransitionState.Adjusted;
    }

    // CTransition::validate_transition
    public TransitionState ValidateTransition(TransitionState state)
    {
        var progressed = true;
        if (state != TransitionState.OK || Path.CheckPos == Path.CurPos)
        {
            progressed = false;
            if (state != TransitionState.OK)
            {
                if (state != TransitionState.Invalid)
                {
                    if (Collisions.LastKnownContactPlaneValid)
                    {
                        Info.VelocityStopped = true;
                        var plane = Collisions.LastKnownContactPlane;
                        var dist = MoveMath.Dot(plane.Normal, Path.GlobalCurrCenter[0]) + plane.D;
                        if (Path.Radius(0) + MovementConstants.Epsilon > MathF.Abs(dist))
                        {
                            Collisions.SetContactPlane(plane, Collisions.LastKnownContactPlaneIsWater);
                            Collisions.ContactPlaneCellKnown = Collisions.LastKnownContactPlaneCellKnown;
                            if (Info.OnWalkable) progressed = true;
                        }
                    }
                    if (!Collisions.CollisionNormalValid) Collisions.SetCollisionNormal(Vector3.UnitZ);
                    Path.SetCheckPos(Path.CurPos);
                    state = TransitionState.OK;
                }
            }
            else
            {
                SetCurrentCheckPos();
            }
        }
        else
        {
            SetCurrentCheckPos();
        }

        if (Collisions.CollisionNormalValid) Collisions.SetSlidingNormal(Collisions.CollisionNormal);

        // A gravity mover counts steps without progress or regained contact (frames_stationary_fall).
        if (!progressed)
        {
            if (Collisions.FramesStationaryFall > 1)
            {
                Collisions.FramesStationaryFall = 3;
                var plane = new Plane(Vector3.UnitZ, Path.Radius(0) - Path.GlobalCenter[0].Z);
                Collisions.SetContactPlane(plane, false);
                Collisions.ContactPlaneCellKnown = true;
                if (!Info.Contact)
                {
                    Collisions.SetCollisionNormal(plane.Normal);
                    Collisions.CollidedWithEnvironment = true;
                }
            }
            else
            {
                Collisions.FramesStationaryFall = Collisions.FramesStationaryFall > 0 ? 2 : 1;
            }
        }
        else
        {
            Collisions.FramesStationaryFall = 0;
        }

        Collisions.LastKnownContactPlaneValid = Collisions.ContactPlaneValid;
        if (Collisions.ContactPlaneValid)
        {
            Collisions.LastKnownContactPlane = Collisions.ContactPlane;
            Collisions.LastKnownContactPlaneCellKnown = Collisions.ContactPlaneCellKnown;
            Collisions.LastKnownContactPlaneIsWater = Collisions.ContactPlaneIsWater;
            Info.Contact = true;
            Info.OnWalkable = ObjectInfo.IsValidWalkable(Collisions.ContactPlane.Normal);
        }
        else
        {
            Info.Contact = false;
            Info.OnWalkable = false;
        }
        return state;
    }

    // CTransition::set_current_check_pos
    private void SetCurrentCheckPos()
    {
        Path.CurPos = Path.CheckPos;
        Path.CacheGlobalCurrCenter();
        Path.SetCheckPos(Path.CurPos);
    }
}
