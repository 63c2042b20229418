using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// Audits one Setup: the shape counts come from <see cref="ShadowShapeBuilder"/> under both policies (the
/// builder dump and batch use) in the chosen pose, the coverage from the retail BSP shapes' poses, and
/// whether the retail pose differs from the placement pose. Pure.
/// </summary>
public static class AuditRowBuilder
{
    public static AuditRow Build(Setup setup, Func<uint, GfxObj?> gfxObjs, float entityScale = 1f, IMotionSource? motions = null, ShapeBuildOptions? pose = null)
    {
        var parts = setup.Parts.Select(id => TryRead(gfxObjs, id)).ToArray();
        var options = (pose ?? new ShapeBuildOptions(ShapePolicy.Retail)) with { Policy = ShapePolicy.Retail, EntityScale = entityScale };
        var retail = ShadowShapeBuilder.Build(setup, gfxObjs, options, motions);
        var union = ShadowShapeBuilder.Build(setup, gfxObjs, options with { Policy = ShapePolicy.Union }, motions);
        var retailPose = options.Pose == PosePolicy.Retail ? retail.Pose
            : ShadowShapeBuilder.Build(setup, gfxObjs, options with { Pose = PosePolicy.Retail }, motions).Pose;

        var bspShapes = retail.Shapes.Where(s => s.CollisionType == CollisionType.Bsp && s.GfxObjId is not null).ToArray();
        var posed = new List<FootprintCoverage.PosedPart>();
        var polygons = 0;
        foreach (var shape in bspShapes)
        {
            var gfx = parts[shape.SourceIndex];
            if (gfx is null) continue;
            polygons += gfx.PhysicsPolygons.Count;
            posed.Add(new FootprintCoverage.PosedPart(gfx, shape.LocalPosition, shape.LocalRotation, shape.Scale));
        }
        var coverage = posed.Count > 0 ? FootprintCoverage.Measure(posed, setup.Radius * entityScale) : null;
        var heightCoverage = posed.Count > 0 ? HeightCoverage.Measure(posed, setup.Height * entityScale) : null;

        var category = retail.PartsHavePhysicsBsp ? AuditCategory.Bsp
            : setup.CylSpheres.Count > 0 ? AuditCategory.Cylinders
            : setup.Spheres.Count > 0 ? AuditCategory.Spheres
            : AuditCategory.None;

        return new AuditRow(
            setup.Id,
            setup.Parts.Count,
            parts.Count(p => p?.HasPhysics == true),
            parts.Count(p => p is null),
            setup.CylSpheres.Count,
            setup.Spheres.Count,
            setup.Radius,
            setup.Height,
            setup.Flags.HasFlag(SetupFlags.HasPhysicsBsp),
            retail.PartsHavePhysicsBsp,
            retail.Shapes.Count,
            union.Shapes.Count,
            polygons,
            retail.Placement.Used,
            union.Placement.Used,
            coverage?.Coverage,
            heightCoverage,
            coverage?.Area,
            category,
            retail.Diagnostics.Select(d => d.Code).Distinct().Order(StringComparer.Ordinal).ToArray())
        {
            PoseSource = retailPose.Source,
            MotionTableId = retailPose.MotionTableId,
            PoseDiffers = retailPose.DiffersFromPlacement,
        };
    }

    /// <summary>An unreadable part counts as missing here; the builder reports it as a diagnostic.</summary>
    private static GfxObj? TryRead(Func<uint, GfxObj?> gfxObjs, uint id)
    {
        try { return gfxObjs(id); }
        catch (DatFormatException) { return null; }
    }
}
