using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>The few words a command's summary line says about the pose a shadow file's parts are in.</summary>
public static class PoseSummary
{
    public static string Describe(ShadowShapeSet set)
    {
        var p = set.Pose;
        var door = p.DoorState is { } state ? $", door {state}{(p.Ethereal ? " (ethereal)" : "")}" : "";
        return p.Source switch
        {
            PoseProvenance.MotionTableSource => $"{p.Policy} pose: MotionTable {JsonIds.Format(p.MotionTableId ?? 0)} Animation {JsonIds.Format(p.AnimationId ?? 0)} frame {p.Frame}{door}",
            PoseProvenance.DefaultAnimationSource => $"{p.Policy} pose: DefaultAnimation {JsonIds.Format(p.AnimationId ?? 0)} frame {p.Frame}{door}",
            _ => $"{p.Policy} pose: placement {set.Placement.Used}{door}",
        };
    }
}
