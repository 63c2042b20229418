using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Core.Chart;

/// <summary>One object to chart: its Setup, how to find its GfxObjs and their compiled PhysicsBSPs, its scale.</summary>
public sealed record ChartSubject(Setup Setup, Func<uint, GfxObj?> GfxObjs, Func<uint, CompiledBsp?> Bsps, float EntityScale = 1f);
