using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// SPHEREPATH: the mover's spheres (local, at the check position, at the current position, and in the space
/// of the part being tested), the current, check and backup positions, and the step's mode flags. The mover's
/// heading is the identity for every walk, so positions are origins: through the identity matrix Frame::cache
/// builds (m0 = m4 = m8 = 1, the rest 0), SPHEREPATH::cache_global_sphere's sums reduce to origin + local, one
/// rounding, as a float sum rounds.
/// </summary>
internal sealed class SpherePath
{
    public int NumSphere;
    public Sphere[] LocalSphere = [];
    public Vector3 LocalLowPoint;

    public Vector3[] GlobalCenter = [];
    public Vector3 GlobalLowPoint;
    public Vector3[] GlobalCurrCenter = [];

    public Vector3 BeginPos;
    public Vector3 EndPos;
    public Vector3 CurPos;
    public Vector3 CheckPos;
    public Vector3 BackupCheckPos;

    public InsertType InsertType = InsertType.Transition;
    public InsertType Backup;
    public bool StepUp;
    public Vector3 StepUpNormal;
    public bool Collide;
    public bool StepDown;
    public float StepDownAmt;
    public float WalkInterp;
    public float WalkableAllowance;
    public bool CheckWalkable;
    public bool ObstructionEthereal;
    public WalkableSurface? Walkable;

    public bool NegPolyHit;
    public bool NegStepUp;
    public Vector3 NegCollisionNormal;

    // The part being tested (CPhysicsPart::find_obj_collisions → cache_localspace_sphere).
    public Sphere[] LocalSpaceSphere = [];
    public Vector3[] LocalSpaceCurrCenter = [];
    public Vector3 LocalSpaceZ;
    public PartPose LocalSpacePos;

    public float Radius(int i) => LocalSphere[i].Radius;

    // SPHEREPATH::init_sphere: at most two spheres, scaled
    public void InitSphere(IReadOnlyList<Sphere> spheres, float scale)
    {
        var source = spheres.Count == 0 ? [MovementConstants.DummySphere] : spheres;
        NumSphere = Math.Min(source.Count, 2);
        LocalSphere = new Sphere[NumSphere];
        for (var i = 0; i < NumSphere; i++)
            LocalSphere[i] = new Sphere(MoveMath.Scale(source[i].Center, scale), source[i].Radius * scale);
        LocalLowPoint = LocalSphere[0].Center with { Z = LocalSphere[0].Center.Z - LocalSphere[0].Radius };
        GlobalCenter = new Vector3[NumSphere];
        GlobalCurrCenter = new Vector3[NumSphere];
        LocalSpaceSphere = new Sphere[NumSphere];
        LocalSpaceCurrCenter = new Vector3[NumSphere];
    }

    // SPHEREPATH::init_path
    public void InitPath(Vector3 begin, Vector3 end)
    {
        BeginPos = begin;
        EndPos = end;
        InsertType = InsertType.Transition;
        CurPos = begin;
        CacheGlobalCurrCenter();
    }

    private static Vector3 LocalToGlobal(Vector3 origin, Vector3 local) => origin + local;

    // SPHEREPATH::cache_global_curr_center
    public void CacheGlobalCurrCenter()
    {
        for (var i = 0; i < NumSphere; i++) GlobalCurrCenter[i] = LocalToGlobal(CurPos, LocalSphere[i].Center);
    }

    // SPHEREPATH::cache_global_sphere (no offset: recomputed from the check position)
    public void CacheGlobalSphere()
    {
        for (var i = 0; i < NumSphere; i++) GlobalCenter[i] = LocalToGlobal(CheckPos, LocalSphere[i].Center);
        GlobalLowPoint = LocalToGlobal(CheckPos, LocalLowPoint);
    }

    // SPHEREPATH::add_offset_to_check_pos: the global spheres are shifted, not recomputed
    public void AddOffsetToCheckPos(Vector3 offset)
    {
        CheckPos += offset;
        for (var i = 0; i < NumSphere; i++) GlobalCenter[i] += offset;
        GlobalLowPoint += offset;
    }

    // SPHEREPATH::set_check_pos
    public void SetCheckPos(Vector3 position)
    {
        CheckPos = position;
        CacheGlobalSphere();
    }

    // SPHEREPATH::save_check_pos
    public void SaveCheckPos() => BackupCheckPos = CheckPos;

    // SPHEREPATH::restore_check_pos
    public void RestoreCheckPos() => SetCheckPos(BackupCheckPos);

    // SPHEREPATH::set_collide
    public void SetCollide(Vector3 normal)
    {
        Collide = true;
        BackupCheckPos = CheckPos;
        StepUpNormal = normal;
        WalkInterp = 1f;
    }

    // SPHEREPATH::set_neg_poly_hit
    public void SetNegPolyHit(bool stepUp, Vector3 normal)
    {
        NegStepUp = stepUp;
        NegPolyHit = true;
        NegCollisionNormal = -normal;
    }

    // SPHEREPATH::cache_localspace_sphere: both spheres at the check and current positions, in part space. Each goes
    // from the mover's own sphere (Position::localtolocal), not from the cached global one, which
    // add_offset_to_check_pos may have shifted with its own rounding.
    // The part's matrix is the caller's, built once per part (Frame::cache), not once per sphere.
    public void CacheLocalSpaceSphere(PartPose pose, in ClientFrameMatrix matrix)
    {
        for (var i = 0; i < NumSphere; i++)
        {
            LocalSpaceSphere[i] = Local(pose, matrix, LocalToGlobal(CheckPos, LocalSphere[i].Center), LocalSphere[i].Radius);
            LocalSpaceCurrCenter[i] = Local(pose, matrix, LocalToGlobal(CurPos, LocalSphere[i].Center), LocalSphere[i].Radius).Center;
        }
        LocalSpacePos = pose;
        LocalSpaceZ = matrix.LocalUp();
    }

    private static Sphere Local(PartPose pose, in ClientFrameMatrix matrix, Vector3 center, float radius)
    {
        var (c, r) = pose.ToLocal(matrix, center, radius);
        return new Sphere(c, r);
    }

    // SPHEREPATH::check_walkables: the remembered walkable still under half the sphere (radius halved in place)
    public bool CheckWalkables()
    {
        if (Walkable is null) return true;
        Walkable.Radius *= 0.5f;
        return PolygonContact.CheckWalkable(Walkable.Polygon, Walkable.Center, Walkable.Radius, Walkable.Up, small: false);
    }

    // SPHEREPATH::step_up_slide
    public TransitionState StepUpSlide(Transition transition)
    {
        transition.Collisions.ClearContactPlane();
        StepUp = false;
        return SphereSlide.Slide(transition, StepUpNormal);
    }

    // SPHEREPATH::precipice_slide: slide along the walkable's edge the sphere crossed
    public TransitionState PrecipiceSlide(Transition transition)
    {
        var walkable = Walkable!;
        if (!PolygonContact.FindCrossedEdge(walkable.Polygon, walkable.Center, walkable.Up, out var localNormal))
        {
            Walkable = null;
            return TransitionState.Collided;
        }
        Walkable = null;
        StepUp = false;
        var normal = walkable.Pose.Matrix.LocalToGlobalVec(localNormal);
        var offset = GlobalCenter[0] - GlobalCurrCenter[0];
        if (MoveMath.Dot(normal, offset) > 0f) normal = -normal;
        return SphereSlide.Slide(transition, normal);
    }
}
