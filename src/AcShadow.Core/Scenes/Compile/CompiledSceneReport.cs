using AcShadow.Core.Chart;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Core.Scenes.Compile;

/// <summary>
/// A compiled landblock: the options, the scene as placed (<see cref="Placed"/>: the LandBlockInfo's
/// objects, then the objects inside its cells), each distinct object's compilation, each indoor cell,
/// and the scene chart's figures.
/// </summary>
public sealed record CompiledSceneReport(
    SceneCompileOptions Options,
    LandblockScene Scene,
    IReadOnlyList<PlacedObject> Placed,
    IReadOnlyDictionary<(SceneObjectKind Kind, uint Id), ObjectCompilation> Compiled,
    IReadOnlyList<CellCompilation> Cells,
    SceneTotals Totals)
{
    public ObjectCompilation? For(SceneObject placed) => Compiled.GetValueOrDefault((placed.Kind, placed.Id));
}

/// <summary>
/// The scene chart's totals: every placed object's and every cell's probes moved into the landblock,
/// asked of the whole scene with every object as retail and with every object as compiled (cells are
/// retail in both) — how many positions, how many agree, and the time per mover position of each.
/// </summary>
public sealed record SceneTotals(int Positions, int Agree, int FalsePass, int FalseBlock, TimingStats Retail, TimingStats Compiled, int RetailShapes, int CompiledShapes)
{
    public double AgreementPercent => Positions == 0 ? 100.0 : 100.0 * Agree / Positions;
}
