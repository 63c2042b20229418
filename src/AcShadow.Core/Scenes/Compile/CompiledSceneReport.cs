using AcShadow.Core.Chart;

namespace AcShadow.Core.Scenes.Compile;

/// <summary>A compiled landblock: the options, the scene as placed, each distinct object's compilation, and the scene chart's figures.</summary>
public sealed record CompiledSceneReport(
    SceneCompileOptions Options,
    LandblockScene Scene,
    IReadOnlyDictionary<(SceneObjectKind Kind, uint Id), ObjectCompilation> Compiled,
    SceneTotals Totals)
{
    public ObjectCompilation? For(SceneObject placed) => Compiled.GetValueOrDefault((placed.Kind, placed.Id));
}

/// <summary>
/// The scene chart's totals: every placed object's probes moved into the landblock, asked of the whole
/// scene with every object as retail and with every object as compiled — how many positions, how many
/// agree, and the time per mover position of each.
/// </summary>
public sealed record SceneTotals(int Positions, int Agree, int FalsePass, int FalseBlock, TimingStats Retail, TimingStats Compiled, int RetailShapes, int CompiledShapes)
{
    public double AgreementPercent => Positions == 0 ? 100.0 : 100.0 * Agree / Positions;
}
