using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Analysis.Chart.Cells;

/// <summary>
/// One indoor cell of a landblock charted: the probes `acshadow scene` lays around it
/// (<see cref="SceneCompiler.CompileCell"/>: a grid over the cell and stability probes on its walls,
/// floors, ceilings and splitting planes, for every mover radius), each moved into the landblock and
/// answered by the cell's retail tree as retail asks a cell (<see cref="CellOverlapQuery"/>,
/// EnvCell::find_env_collisions), and that query timed. A cell has no cheaper model to compare (every
/// cheaper model is a solid that would fill the room), so the chart records where its walls block.
/// </summary>
internal sealed record CellChart(CellCompilation Cell, bool[] Answers, TimingStats Timing)
{
    public const string Model = CellCompilation.Model;

    public int Blocked => Answers.Count(a => a);

    public static CellChart Of(EnvCell cell, CellStructures structures, ChartOptions options, IQueryTimer timer)
    {
        var compiled = SceneCompiler.CompileCell(cell, structures, options);
        if (compiled.Bsp is null || compiled.Probes.Count == 0) return new CellChart(compiled, [], TimingStats.Of([]));
        var query = new PreparedModel(new CellOverlapQuery(compiled.Physics!, cell.Position.Position, cell.Position.Rotation), [], []);
        var positions = compiled.Probes.Select(p => p with { Center = compiled.Frame.ToEntity(p.Center) }).ToArray();
        return new CellChart(compiled, ChartRunner.Answers(query, positions), timer.Measure("cell: retail", query, positions, options));
    }
}
