using AcShadow.Analysis.Chart;
using AcShadow.Core.Scenes;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Analysis.Compile;

/// <summary>
/// A compiled landblock: the options, the scene as placed (<see cref="Placed"/>: the LandBlockInfo's
/// objects, then the objects inside its cells), each distinct object's compilation, each indoor cell,
/// and the scene chart's figures.
/// </summary>
internal sealed record CompiledSceneReport(
    SceneCompileOptions Options,
    LandblockScene Scene,
    IReadOnlyList<PlacedObject> Placed,
    IReadOnlyDictionary<(SceneObjectKind Kind, uint Id), ObjectCompilation> Compiled,
    IReadOnlyList<CellCompilation> Cells,
    SceneTotals Totals)
{
    public ObjectCompilation? For(SceneObject placed) => Compiled.GetValueOrDefault((placed.Kind, placed.Id));

    /// <summary>The probes checked over the whole scene, every distinct object's and every cell's, by kind.</summary>
    public ProbeCounts Probes() => ProbeCounts.Of(Compiled.Values.SelectMany(c => c.Probes).Concat(Cells.SelectMany(c => c.Probes)));
}

/// <summary>
/// The scene chart's totals: every placed object's and every cell's probes moved into the landblock,
/// asked of the whole scene with every object as retail and with every object as compiled (cells are
/// retail in both) — how many positions, how many agree, the time per mover position of each, and the
/// counted operations per position of each (<see cref="SceneCost"/>: the same on every run). Both ask
/// through the land-cell partition; <see cref="Exhaustive"/> and <see cref="ExhaustiveOps"/> are all-retail
/// asked of every object and cell, the walk the partition replaced; <see cref="NarrowFloorOps"/> what no broad phase
/// can save.
/// </summary>
internal sealed record SceneTotals(int Positions, int Agree, int FalsePass, int FalseBlock, TimingStats Retail, TimingStats Compiled, int RetailShapes, int CompiledShapes)
{
    public double RetailOps { get; init; }
    public double CompiledOps { get; init; }
    public TimingStats Exhaustive { get; init; } = TimingStats.Of([]);
    public double ExhaustiveOps { get; init; }

    /// <summary>All-retail's narrow phase alone (<see cref="SceneWalk.NarrowFloor"/>): no broad phase asks for less.</summary>
    public double NarrowFloorOps { get; init; }

    public double AgreementPercent => Positions == 0 ? 100.0 : 100.0 * Agree / Positions;
}
