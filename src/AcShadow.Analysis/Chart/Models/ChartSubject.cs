using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Models;

/// <summary>
/// One object to chart: its Setup, how to find its GfxObjs and their compiled PhysicsBSPs, its scale, and
/// how its parts are posed (<see cref="Pose"/>: pose, door state and motion table; <see cref="Motions"/>:
/// where motion tables and animations are read).
/// </summary>
internal sealed record ChartSubject(Setup Setup, Func<uint, GfxObj?> GfxObjs, Func<uint, CompiledBsp?> Bsps, float EntityScale = 1f)
{
    public ShapeBuildOptions? Pose { get; init; }
    public IMotionSource? Motions { get; init; }

    /// <summary>The build options a model uses for <paramref name="policy"/>: the subject's pose and scale.</summary>
    public ShapeBuildOptions Options(ShapePolicy policy) =>
        (Pose ?? new ShapeBuildOptions(policy)) with { Policy = policy, EntityScale = EntityScale };

    /// <summary>Builds the subject's shapes under <paramref name="options"/>.</summary>
    public ShadowShapeSet Build(ShapeBuildOptions options) => ShadowShapeBuilder.Build(Setup, GfxObjs, options, Motions);
}
