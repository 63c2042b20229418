using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Shapes;

/// <summary>
/// Turns a Setup into the collision shapes an entity registers. Pure: the Setup and a lookup of its parts
/// (<see cref="PartPhysics"/>, or whole GfxObjs) in, a <see cref="ShadowShapeSet"/> out. Everything skipped becomes a <see cref="Diagnostic"/>.
/// Parts are posed as <see cref="RetailPoseResolver"/> decides (motion tables and animations from
/// <paramref name="motions"/>; without it, a Setup that names them gets a diagnostic and its placement pose).
/// </summary>
public static class ShadowShapeBuilder
{
    public static ShadowShapeSet Build(Setup setup, Func<uint, GfxObj?> gfxObjs, ShapeBuildOptions options, IMotionSource? motions = null) =>
        Build(setup, id => gfxObjs(id) is { } gfx ? PartPhysics.Of(gfx) : null, options, motions);

    /// <summary>As above, each part looked up as the little the shapes need of it (<see cref="PartPhysics"/>; a lookup may throw <see cref="DatFormatException"/> as a GfxObj read does).</summary>
    public static ShadowShapeSet Build(Setup setup, Func<uint, PartPhysics?> partPhysics, ShapeBuildOptions options, IMotionSource? motions = null)
    {
        var diagnostics = new List<Diagnostic>();
        var scale = options.EntityScale;
        var pose = RetailPoseResolver.Resolve(setup, options.PoseSettings, motions, diagnostics);
        var placementFrame = pose.Placement;
        var placement = PlacementResolver.Describe(placementFrame);
        var provenance = pose.MotionFrames is null ? pose.Provenance : pose.Provenance with { DiffersFromPlacement = ReportMoves(setup, pose, diagnostics) };
        var parts = LookUpParts(setup, partPhysics, diagnostics);
        // The dat stores exactly NumParts frames per placement; a source that does not is reported here,
        // and a part without a frame is reported where it is skipped (no-pose).
        if (placementFrame is { } used && used.Frames.Count != parts.Length)
            diagnostics.Add(new(DiagnosticCodes.FrameCount,
                $"placement {used.Name} has {used.Frames.Count} frame(s) for {parts.Length} part(s): {(used.Frames.Count > parts.Length ? "the extra frames are ignored" : "parts past the last frame get no pose")}"));
        var partsHaveBsp = parts.Any(p => p?.HasPhysics == true);

        // CPartArray::CacheHasPhysicsBSP computes the state from the parts; Setup.Flags' bit is not read.
        var flagSaysBsp = setup.Flags.HasFlag(SetupFlags.HasPhysicsBsp);
        if (flagSaysBsp != partsHaveBsp)
            diagnostics.Add(new(DiagnosticCodes.FlagMismatch,
                $"Setup.Flags HasPhysicsBSP is {(flagSaysBsp ? "set" : "clear")} but {(partsHaveBsp ? "a part has" : "no part has")} a PhysicsBSP; the parts decide"));

        var shapes = options.Policy switch
        {
            ShapePolicy.Retail => BuildRetail(setup, parts, partsHaveBsp, pose, scale, diagnostics),
            ShapePolicy.Union => BuildUnion(setup, parts, pose, scale, diagnostics),
            _ => throw new ArgumentOutOfRangeException(nameof(options)),
        };
        if (shapes.Count == 0)
            diagnostics.Add(new(DiagnosticCodes.NoShapes, "no collision shapes: nothing of this object collides"));
        foreach (var shape in shapes.Where(s => !IsFinite(s)))
            diagnostics.Add(new(DiagnosticCodes.NonFinite, $"{Describe(shape)}: non-finite position, rotation, scale or radius (NaN or infinity in the dat)"));
        // The Setup's own primitives are recorded in every shadow file and drawn by view even when the policy
        // builds no shape from them (a BSP object's Spheres, its Radius x Height): a non-finite one is said too.
        foreach (var problem in NonFinitePrimitives(setup).Where(p => !diagnostics.Any(d => d.Code == DiagnosticCodes.NonFinite && d.Message.StartsWith(p.Split(':')[0] + ":", StringComparison.Ordinal))))
            diagnostics.Add(new(DiagnosticCodes.NonFinite, problem));
        return new ShadowShapeSet(setup.Id, options.Policy, placement, scale, partsHaveBsp, shapes, diagnostics) { Pose = provenance };
    }

    /// <summary>
    /// Says, in one diagnostic, which parts the motion pose moves more than 1 mm or 0.1° from where the
    /// placement pose puts them; true when any does.
    /// </summary>
    private static bool ReportMoves(Setup setup, ResolvedPose pose, List<Diagnostic> diagnostics)
    {
        var moves = PoseMoves.Between(setup, pose);
        if (moves.Count == 0) return false;
        var p0 = pose.Provenance;
        var by = p0.Source == PoseProvenance.DefaultAnimationSource ? "the DefaultAnimation" : $"MotionTable 0x{p0.MotionTableId:X8}";
        diagnostics.Add(new(PoseDiagnosticCodes.PoseMoved,
            $"the retail pose ({by}, Animation 0x{p0.AnimationId:X8} frame {p0.Frame}) moves {string.Join(", ", moves)} from placement {pose.Placement?.Name ?? PlacementResolution.NoneName}; --pose placement gives the placement pose"));
        return true;
    }

    private static PartPhysics?[] LookUpParts(Setup setup, Func<uint, PartPhysics?> partPhysics, List<Diagnostic> diagnostics)
    {
        var parts = new PartPhysics?[setup.Parts.Count];
        for (var i = 0; i < parts.Length; i++)
        {
            var id = setup.Parts[i];
            try
            {
                parts[i] = partPhysics(id);
                if (parts[i] is null)
                    diagnostics.Add(new(DiagnosticCodes.MissingGfxObj, $"part {i} (GfxObj 0x{id:X8}) is not in the dat: it contributes nothing"));
            }
            catch (DatFormatException e)
            {
                diagnostics.Add(new(DiagnosticCodes.UnreadableGfxObj, $"part {i} (GfxObj 0x{id:X8}) cannot be read: {e.Message}"));
            }
        }
        return parts;
    }

    /// <summary>
    /// CPhysicsObj::FindObjCollisions picks one family: parts' BSPs when any part has one, else
    /// CylSpheres, else Spheres.
    /// </summary>
    private static List<ShadowShape> BuildRetail(Setup setup, PartPhysics?[] parts, bool partsHaveBsp, ResolvedPose pose, float scale, List<Diagnostic> diagnostics)
    {
        var shapes = new List<ShadowShape>();
        if (partsHaveBsp)
        {
            var useDefaultScale = setup.DefaultScale.Count == parts.Length;
            if (setup.DefaultScale.Count > 0 && !useDefaultScale)
                diagnostics.Add(new(DiagnosticCodes.DefaultScaleCount, $"DefaultScale has {setup.DefaultScale.Count} entries for {parts.Length} parts: ignored"));
            for (var i = 0; i < parts.Length; i++)
            {
                var part = parts[i];
                if (part?.HasPhysics != true) continue;
                if (!TryRetailPose(pose, parts.Length, i, out var partPose, diagnostics, setup.Parts[i])) continue;
                var partScale = scale;
                if (useDefaultScale)
                {
                    // CPhysicsPart::find_obj_collisions passes GfxObjScale.Z as the uniform BSP scale.
                    var s = setup.DefaultScale[i];
                    partScale *= s.Z;
                    if (s.X != s.Z || s.Y != s.Z)
                        diagnostics.Add(new(DiagnosticCodes.NonUniformScale, string.Create(System.Globalization.CultureInfo.InvariantCulture, $"part {i} (GfxObj 0x{part.Id:X8}) DefaultScale ({s.X}, {s.Y}, {s.Z}) is not uniform; BSP collision uses Z")));
                }
                shapes.Add(BspShape(i, part, partPose, scale, partScale));
            }
            return shapes;
        }
        for (var i = 0; i < setup.CylSpheres.Count; i++)
        {
            var c = setup.CylSpheres[i];
            if (c.Radius <= 0f) diagnostics.Add(new(DiagnosticCodes.ZeroRadius, $"CylSphere {i} has radius {c.Radius}"));
            shapes.Add(new ShadowShape(ShapeSource.CylSphere, i, null, CollisionType.Cylinder, c.Origin * scale, Quaternion.Identity, scale, c.Radius * scale, c.Height * scale, null));
        }
        if (shapes.Count > 0) return shapes;
        for (var i = 0; i < setup.Spheres.Count; i++)
        {
            var s = setup.Spheres[i];
            if (s.Radius <= 0f) diagnostics.Add(new(DiagnosticCodes.ZeroRadius, $"Sphere {i} has radius {s.Radius}"));
            shapes.Add(new ShadowShape(ShapeSource.Sphere, i, null, CollisionType.Sphere, s.Center * scale, Quaternion.Identity, scale, s.Radius * scale, 0f, null));
        }
        return shapes;
    }

    /// <summary>
    /// CPartArray::UpdateParts poses min(NumParts, frames) parts: by the current animation frame when there
    /// is one, else by the placement frame; with neither, a one-part object sits at the entity origin and the
    /// parts of a multi-part object have no meaningful pose.
    /// </summary>
    private static bool TryRetailPose(ResolvedPose resolved, int partCount, int index, out Frame pose, List<Diagnostic> diagnostics, uint gfxId)
    {
        if (resolved.MotionFrames is { } motion && index < motion.Count) { pose = motion[index]; return true; }
        if (resolved.Placement is { } frame)
        {
            if (index < frame.Frames.Count) { pose = frame.Frames[index]; return true; }
            diagnostics.Add(new(DiagnosticCodes.NoPose, $"part {index} (GfxObj 0x{gfxId:X8}): placement {frame.Name} has only {frame.Frames.Count} frame(s); the part gets no pose and is skipped"));
            pose = default;
            return false;
        }
        if (partCount == 1) { pose = Frame.Identity; return true; }
        diagnostics.Add(new(DiagnosticCodes.NoPose, $"part {index} (GfxObj 0x{gfxId:X8}): the Setup has neither a Resting nor a Default placement, so a multi-part object's part has no pose; skipped"));
        pose = default;
        return false;
    }

    /// <summary>The design's union builder, reproduced exactly so its divergences can be measured.</summary>
    private static List<ShadowShape> BuildUnion(Setup setup, PartPhysics?[] parts, ResolvedPose resolved, float scale, List<Diagnostic> diagnostics)
    {
        var shapes = new List<ShadowShape>();
        for (var i = 0; i < setup.CylSpheres.Count; i++)
        {
            var c = setup.CylSpheres[i];
            if (c.Radius <= 0f) { diagnostics.Add(new(DiagnosticCodes.ZeroRadius, $"CylSphere {i} has radius {c.Radius}: skipped")); continue; }
            var height = c.Height > 0f ? c.Height : c.Radius * 4f;
            shapes.Add(new ShadowShape(ShapeSource.CylSphere, i, null, CollisionType.Cylinder, c.Origin * scale, Quaternion.Identity, scale, c.Radius * scale, height * scale, null));
        }
        if (setup.CylSpheres.Count == 0)
        {
            for (var i = 0; i < setup.Spheres.Count; i++)
            {
                var s = setup.Spheres[i];
                if (s.Radius <= 0f) { diagnostics.Add(new(DiagnosticCodes.ZeroRadius, $"Sphere {i} has radius {s.Radius}: skipped")); continue; }
                shapes.Add(new ShadowShape(ShapeSource.Sphere, i, null, CollisionType.Cylinder, s.Center * scale, Quaternion.Identity, scale, s.Radius * scale, s.Radius * 2f * scale, null));
            }
        }
        for (var i = 0; i < parts.Length; i++)
        {
            var part = parts[i];
            if (part?.HasPhysics != true) continue;
            var frame = resolved.Placement;
            var pose = resolved.MotionFrames is { } motion && i < motion.Count ? motion[i]
                : frame is not null && i < frame.Frames.Count ? frame.Frames[i] : Frame.Identity;
            shapes.Add(BspShape(i, part, pose, scale, scale));
        }
        return shapes;
    }

    private static ShadowShape BspShape(int partIndex, PartPhysics part, Frame pose, float entityScale, float partScale)
    {
        var root = part.BspBound!.Value;
        var position = pose.Position * entityScale;
        // The root sphere's centre out of the part's frame as the client holds it (Frame::combine, Frame::localtoglobal).
        var center = PartPose.InEntity(position, pose.Rotation, partScale).ToEntity(root.Center);
        var radius = root.Radius * partScale;
        return new ShadowShape(ShapeSource.Part, partIndex, part.Id, CollisionType.Bsp, position, pose.Rotation, partScale, radius, 0f, new Sphere(center, radius));
    }

    /// <summary>The Setup's CylSpheres, Spheres, Radius and Height that hold NaN or infinity, each as a message.</summary>
    private static IEnumerable<string> NonFinitePrimitives(Setup setup)
    {
        static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
        for (var i = 0; i < setup.CylSpheres.Count; i++)
            if (!Finite(setup.CylSpheres[i].Origin) || !float.IsFinite(setup.CylSpheres[i].Radius) || !float.IsFinite(setup.CylSpheres[i].Height))
                yield return $"CylSphere {i}: non-finite origin, radius or height (NaN or infinity in the dat)";
        for (var i = 0; i < setup.Spheres.Count; i++)
            if (!Finite(setup.Spheres[i].Center) || !float.IsFinite(setup.Spheres[i].Radius))
                yield return $"Sphere {i}: non-finite center or radius (NaN or infinity in the dat)";
        if (!float.IsFinite(setup.Radius) || !float.IsFinite(setup.Height))
            yield return string.Create(System.Globalization.CultureInfo.InvariantCulture, $"Setup Radius x Height: non-finite ({setup.Radius} x {setup.Height}; NaN or infinity in the dat)");
    }

    private static bool IsFinite(ShadowShape s) =>
        float.IsFinite(s.LocalPosition.X) && float.IsFinite(s.LocalPosition.Y) && float.IsFinite(s.LocalPosition.Z)
        && float.IsFinite(s.LocalRotation.X) && float.IsFinite(s.LocalRotation.Y) && float.IsFinite(s.LocalRotation.Z) && float.IsFinite(s.LocalRotation.W)
        && float.IsFinite(s.Scale) && float.IsFinite(s.Radius) && float.IsFinite(s.CylHeight);

    private static string Describe(ShadowShape s) => s.Source switch
    {
        ShapeSource.Part => $"part {s.SourceIndex} (GfxObj 0x{s.GfxObjId:X8})",
        ShapeSource.CylSphere => $"CylSphere {s.SourceIndex}",
        _ => $"Sphere {s.SourceIndex}",
    };
}
