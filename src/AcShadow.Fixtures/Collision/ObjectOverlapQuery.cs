using System.Numerics;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// "Does a query sphere at entity-space centre c with radius r overlap the object?" over a
/// <see cref="ShadowShapeSet"/>: blocked when any shape blocks. BSP shapes move the sphere into the part's
/// space (<see cref="PosedQuery"/>, refused first by the part's reach in the entity frame) and ask the part's tree
/// (<see cref="BspSphereQuery"/>); Cylinder shapes use <see cref="CylinderSphereTest"/> with the base at LocalPosition;
/// Sphere shapes use <see cref="SphereSphereTest"/>. A shape that cannot be tested (no PhysicsBSP dump, NaN
/// in its frame, a scale that is zero or not finite) is skipped with a diagnostic naming it.
/// </summary>
internal sealed class ObjectOverlapQuery : ISphereOverlap
{
    private readonly ISphereOverlap[] _checks;

    public IReadOnlyList<PreparedShape> Shapes { get; }
    public IReadOnlyList<Diagnostic> Diagnostics { get; }

    /// <summary>One query per shape, in <see cref="Shapes"/> order (CPhysicsObj::FindObjCollisions asks each part in turn).</summary>
    public IReadOnlyList<ISphereOverlap> Parts => _checks;

    private ObjectOverlapQuery(ISphereOverlap[] checks, IReadOnlyList<PreparedShape> shapes, IReadOnlyList<Diagnostic> diagnostics)
    {
        _checks = checks;
        Shapes = shapes;
        Diagnostics = diagnostics;
    }

    public static ObjectOverlapQuery Create(IEnumerable<ShadowShape> shapes, Func<uint, CompiledBsp?> bsps)
    {
        var log = new DiagnosticLog();
        var checks = new List<ISphereOverlap>();
        var prepared = new List<PreparedShape>();
        var queries = new Dictionary<uint, ISphereOverlap>();
        foreach (var shape in shapes)
        {
            var name = PreparedShape.NameOf(shape);
            if (!Vec.IsFinite(shape.LocalPosition) || !float.IsFinite(shape.Radius) || !float.IsFinite(shape.CylHeight))
            {
                log.Add(CollisionDiagnosticCodes.SkippedShape, $"{name}: NaN or infinity in its position or size; skipped");
                continue;
            }
            switch (shape.CollisionType)
            {
                case CollisionType.Bsp:
                    if (Prepare(shape, name, bsps, log) is not { } part) continue;
                    var id = part.Bsp!.GfxObjId;
                    if (!queries.TryGetValue(id, out var query))
                        queries[id] = query = new BspSphereQuery(part.Bsp);
                    checks.Add(new PosedQuery(part.Pose, query));
                    prepared.Add(part);
                    break;
                case CollisionType.Cylinder:
                    checks.Add(new CylinderShapeQuery(shape.LocalPosition, shape.Radius, shape.CylHeight));
                    prepared.Add(new PreparedShape(shape, name, new PartPose(shape.LocalPosition, Quaternion.Identity, 1f), null));
                    break;
                default:
                    checks.Add(new SphereShapeQuery(shape.LocalPosition, shape.Radius));
                    prepared.Add(new PreparedShape(shape, name, new PartPose(shape.LocalPosition, Quaternion.Identity, 1f), null));
                    break;
            }
        }
        return new ObjectOverlapQuery([.. checks], prepared, log.ToList());
    }

    public static ObjectOverlapQuery Create(ShadowShapeSet set, Func<uint, CompiledBsp?> bsps) =>
        Create(set.Shapes, bsps);

    /// <summary>The same object with each part's tree asked through its <see cref="BspReachGrid"/>s for the scene's mover radii: the same answers.</summary>
    internal ObjectOverlapQuery Indexed(BspReachGrids grids) =>
        new([.. _checks.Select(c => c is PosedQuery { PartQuery: BspSphereQuery tree } part ? new PosedQuery(part.Pose, grids.Index(tree, part.Pose)) : c)], Shapes, Diagnostics);

    public bool Overlaps(Vector3 center, float radius)
    {
        if (!SphereBounds.IsValidProbe(center, radius)) return false;
        foreach (var check in _checks)
            if (check.Overlaps(center, radius)) return true;
        return false;
    }

    private static PreparedShape? Prepare(ShadowShape shape, string name, Func<uint, CompiledBsp?> bsps, DiagnosticLog log)
    {
        if (shape.GfxObjId is not { } id) { log.Add(CollisionDiagnosticCodes.SkippedShape, $"{name}: a BSP shape without a GfxObj id; skipped"); return null; }
        if (!(shape.Scale > 0f) || !float.IsFinite(shape.Scale)) { log.Add(CollisionDiagnosticCodes.SkippedShape, FormattableString.Invariant($"{name}: scale {shape.Scale} cannot be divided by; skipped")); return null; }
        var rotation = shape.LocalRotation;
        if (!Vec.IsFinite(rotation)) { log.Add(CollisionDiagnosticCodes.SkippedShape, $"{name}: NaN or infinity in its rotation; skipped"); return null; }
        var lengthSquared = rotation.X * rotation.X + rotation.Y * rotation.Y + rotation.Z * rotation.Z + rotation.W * rotation.W;
        if (!(lengthSquared > 1e-12f)) { log.Add(CollisionDiagnosticCodes.SkippedShape, $"{name}: zero rotation quaternion; skipped"); return null; }
        if (MathF.Abs(lengthSquared - 1f) > 1e-4f)
            log.Add(CollisionDiagnosticCodes.NormalisedRotation, FormattableString.Invariant($"{name}: rotation quaternion of length {MathF.Sqrt(lengthSquared):0.######} normalised"));
        var bsp = bsps(id);
        if (bsp is null) { log.Add(CollisionDiagnosticCodes.SkippedShape, $"{name}: no PhysicsBSP for GfxObj 0x{id:X8}; skipped"); return null; }
        return new PreparedShape(shape, name, PartPose.InEntity(shape.LocalPosition, rotation, shape.Scale), bsp);
    }
}
