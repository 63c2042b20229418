using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Cells;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Cells;
using AcShadow.Fixtures.Collision;
using AcShadow.Tests.Scenes;

namespace AcShadow.Tests.Chart;

/// <summary>
/// A landblock chart probes its indoor cells with the probes `acshadow scene` lays (one code path):
/// a probe against a sample cell wall is in the cell's chart, answered as the cell's retail tree answers.
/// </summary>
public class CellChartTests
{
    [Fact]
    public void A_probe_against_the_ground_floors_wall_is_charted_with_retails_answer()
    {
        var scene = SceneCompileTests.SampleScene();
        var structures = new CellStructures(SampleChart.Subjects.Value.Dat);
        var options = new ChartOptions { Spacing = 1f };
        var cell = scene.Cells.First(c => c.Id == 0xA9B40100);
        var chart = CellChart.Of(cell, structures, options, new FixedTimer());

        // The same probes the scene compiler lays around the cell.
        var compiled = SceneCompiler.CompileCell(cell, structures, options);
        Assert.Equal(compiled.Probes, chart.Cell.Probes);
        var bsp = Assert.IsType<CompiledBsp>(chart.Cell.Bsp);

        // A face probe just inside a wall's reach blocks, its twin just outside does not, and the blocked one
        // touches one of the cell's own polygons: the answer is the wall's.
        var faces = Enumerable.Range(0, chart.Cell.Probes.Count).Where(i => chart.Cell.Probes[i].Kind == ProbeKind.Face).ToArray();
        var blocked = faces.Where(i => chart.Answers[i]).ToArray();
        Assert.NotEmpty(blocked);
        Assert.Contains(faces, i => !chart.Answers[i]);
        Assert.Contains(blocked, i => bsp.Polygons.Any(p => PolygonSphereTest.Touches(p, chart.Cell.Probes[i].Center, chart.Cell.Probes[i].Radius)));

        // Answered as the scene asks a cell: moved into the landblock, then through the cell's frame.
        var query = new CellOverlapQuery(chart.Cell.Physics!, cell.Position.Position, cell.Position.Rotation);
        for (var i = 0; i < chart.Cell.Probes.Count; i += 97)
            Assert.Equal(query.Overlaps(chart.Cell.Frame.ToEntity(chart.Cell.Probes[i].Center), chart.Cell.Probes[i].Radius), chart.Answers[i]);

        var csv = CellsCsv.Write([chart]).Split('\n');
        Assert.StartsWith("0xA9B40100,", csv[1]);
        Assert.Contains(",retail," + chart.Cell.Probes.Count.ToString(System.Globalization.CultureInfo.InvariantCulture) + ",", csv[1]);
    }
}
