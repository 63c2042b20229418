using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Doctor;

/// <summary>
/// The motion pose checked on one Setup (motion-pose.md): a Setup that names a DefaultAnimation or a
/// motion table (its own, or the door catalog's) is posed by the animation frame current right after
/// creation. Counts the Setups the motion pose applies to, those that fall back to the placement pose
/// because a table, a default state, an animation or its frame is missing or unreadable (an animation short of
/// part frames still poses the parts it has; a missing animation is dropped and another may still pose), and those whose
/// motion pose moves a part from where the placement pose puts it.
/// </summary>
internal static class MotionPoseInspection
{
    private static readonly PoseSettings RetailPose = new ShapeBuildOptions(ShapePolicy.Retail).PoseSettings;

    private static readonly HashSet<string> FallBacks = new(StringComparer.Ordinal)
    {
        PoseDiagnosticCodes.MissingMotionTable, PoseDiagnosticCodes.UnreadableMotionTable, PoseDiagnosticCodes.NoDefaultState,
        PoseDiagnosticCodes.MissingAnimation, PoseDiagnosticCodes.UnreadableAnimation, PoseDiagnosticCodes.AnimationFrame,
    };

    public static void Inspect(Setup setup, IMotionSource motions, DoctorTallies t)
    {
        var diagnostics = new List<Diagnostic>();
        var pose = RetailPoseResolver.Resolve(setup, RetailPose, motions, diagnostics);
        var animated = pose.Provenance.Source != PoseProvenance.PlacementSource;
        var fellBack = !animated && diagnostics.Any(d => FallBacks.Contains(d.Code));
        if (!animated && !fellBack) return;
        t.WithMotion.Add();
        if (animated) t.MotionPosed.Add();
        if (fellBack) t.PoseFellBack.Add(setup.Id);
        if (PoseMoves.Between(setup, pose).Count > 0) t.PoseDiffers.Add(setup.Id);
    }
}
