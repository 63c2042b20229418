using AcShadow.Forge;
using System.Numerics;
using System.Text.Json;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Compile;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Scenes;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Scenes;
using AcShadow.Forging;
using AcShadow.Tests.Chart;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// `acshadow scene` on the sample landblock: every object gets the first model of the ladder that
/// gives retail's answer on every probe; the compiled scene agrees with every-object-retail everywhere
/// it was checked; the tolerance never admits a false pass; the consumer library loads the file and
/// answers as retail does.
/// </summary>
public class SceneCompileTests
{
    /// <summary>The sample landblock as `acshadow scene` plans it: its objects and its indoor cells (the cottage).</summary>
    internal static LandblockScene SampleScene()
    {
        var cell = DatDatabase.Open(new MemoryStream(SampleDat.CellBytes!), "client_cell_1.dat");
        return BatchPlanner.Plan(new BatchSelection(false, false, null, SampleSpecAuthor.Landblock), SampleChart.Subjects.Value.Dat, cell, []).Scene!;
    }

    private const uint GroundFloor = 0xA9B40100, Cellar = 0xA9B40101;

    internal static readonly Lazy<CompiledSceneReport> Exact = new(() => Compile(new SceneCompileOptions()));

    internal static CompiledSceneReport Compile(SceneCompileOptions options) =>
        SceneCompiler.Compile(SampleScene(), SampleChart.Subjects.Value, options, new FixedTimer());

    [Fact]
    public void The_compiled_sample_landblock_gives_retails_answer_everywhere_and_models_less_where_it_can()
    {
        var report = Exact.Value;
        Assert.Equal(report.Totals.Positions, report.Totals.Agree);
        Assert.True(report.Totals.Positions > 10_000);
        var models = report.Placed.ToDictionary(p => p.Object.Id, p => report.For(p.Object)!.Model);
        // The bare octagonal column is convex: its hull is exact.
        Assert.Equal("part-hulls", models[SampleSpecAuthor.Column]);
        // The door keeps its BSP: a jamb with its threshold is neither a box nor a hull, and the evidence says so.
        Assert.Equal("retail", models[SampleSpecAuthor.DoorSetup]);
        var door = report.Compiled[(SceneObjectKind.Setup, SampleSpecAuthor.DoorSetup)];
        Assert.Equal(ModelLadder.Names.Order(), door.Candidates.Select(c => c.Model).Order());
        Assert.All(door.Candidates.SkipLast(1), c => Assert.False(c.Accepted));
        Assert.True(door.Candidates.Single(c => c.Model == "part-hulls").FalseBlock > 0);
        foreach (var c in report.Compiled.Values)
        {
            Assert.Equal(0, c.FalsePass);
            Assert.Equal(0, c.FalseBlock);
            Assert.All(ProbeKinds.Stability, k => Assert.True(ChartProbes.Count(c.Probes, k) > 0));
        }
    }

    [Fact]
    public void Models_are_tried_fewest_counted_operations_first_so_none_chosen_costs_more_than_retail()
    {
        var report = Exact.Value;
        foreach (var c in report.Compiled.Values.Where(c => c.Candidates.Count > 0))
        {
            // Tried in order of counted cost; every one before the chosen model was refused.
            Assert.Equal(c.Candidates.Select(k => k.OpsPerQuery).Order(), c.Candidates.Select(k => k.OpsPerQuery));
            Assert.True(c.Candidates[^1].Accepted);
            Assert.Equal(c.Model, c.Candidates[^1].Model);
            Assert.All(c.Candidates.SkipLast(1), k => Assert.False(k.Accepted));
            Assert.True(c.ChosenOps <= c.RetailOps, $"0x{c.Id:X8}: {c.Model} counts {c.ChosenOps}, retail {c.RetailOps}");
        }
        // The column's hull counts fewer operations than its tree; so does the scene that uses it.
        var column = report.Compiled[(SceneObjectKind.GfxObj, SampleSpecAuthor.Column)];
        Assert.True(column.ChosenOps < column.RetailOps);
        Assert.True(report.Totals.CompiledOps < report.Totals.RetailOps, $"{report.Totals.CompiledOps} vs {report.Totals.RetailOps}");
        // Counts, not timings: the same on every compile.
        var again = Compile(new SceneCompileOptions());
        Assert.Equal(report.Totals.RetailOps, again.Totals.RetailOps);
        Assert.Equal(report.Compiled.Values.Select(c => c.ChosenOps), again.Compiled.Values.Select(c => c.ChosenOps));
    }

    [Fact]
    public void Equal_counts_keep_ladder_order_and_a_model_counting_more_than_retail_comes_after_it()
    {
        // spheres, part-spheres, fallback-cylinder, part-boxes, part-hulls, retail
        Assert.Equal([0, 1, 2, 3, 4, 5], ModelLadder.ByCost([1, 1, 2, 7, 21, 40]));
        // A hull of many faces against a shallow tree: retail is tried (and, always qualifying, chosen) first.
        Assert.Equal([1, 2, 3, 5, 0, 4], ModelLadder.ByCost([9, 1, 2, 7, 60, 8]));
        Assert.Equal([0, 1, 5, 2, 3, 4], ModelLadder.ByCost([0, 1, 3, 3, 3, 2]));
    }

    [Fact]
    public void Bsp_dumps_are_written_only_for_objects_still_modelled_by_retail()
    {
        var report = Exact.Value;
        var needed = CompiledSceneWriter.BspGfxObjs(report);
        var retailParts = report.Compiled.Values.Where(c => c.Model == "retail")
            .SelectMany(c => c.Chosen!.Shapes.Select(s => s.Shape.GfxObjId!.Value)).Distinct().Order();
        Assert.Equal(retailParts, needed);
        var files = CompiledSceneFiles.Render(report, id => SampleChart.Subjects.Value.Bsps.Get(id) is null ? null
            : AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!));
        Assert.Equal(needed.Select(AcShadow.Fixtures.Formats.FileFormats.Bsp.PathFor), files.Select(f => f.RelativePath).Where(p => p.StartsWith("gfxobjs/")));
    }

    [Fact]
    public void A_tolerance_admits_false_blocks_but_never_a_false_pass()
    {
        var report = Compile(new SceneCompileOptions { TolerancePercent = 100 });
        foreach (var c in report.Compiled.Values.Where(c => c.Probes.Count > 0))
        {
            Assert.Equal(0, c.FalsePass);
            Assert.All(c.Candidates.Where(k => k.FalsePass > 0), k => Assert.False(k.Accepted));
        }
        // The Setup's soda-can sphere lets movers through the closed door: refused; a bounding sphere per part only blocks too much.
        var door = report.Compiled[(SceneObjectKind.Setup, SampleSpecAuthor.DoorSetup)];
        Assert.False(door.Candidates[0].Accepted);
        Assert.Equal("part-spheres", door.Model);
        Assert.Equal(0, report.Totals.FalsePass);
        Assert.True(report.Totals.FalseBlock > 0);
    }

    [Fact]
    public void The_compiled_scene_is_the_same_bytes_every_run_and_the_consumer_library_answers_as_retail_does()
    {
        using var dir = new TempDir();
        var report = Exact.Value;
        var files = CompiledSceneFiles.Render(report, id => AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!));
        Assert.Equal(files.Select(f => f.Content.ToArray()), CompiledSceneFiles.Render(Compile(new SceneCompileOptions()), id => AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!)).Select(f => f.Content.ToArray()));
        foreach (var f in files)
        {
            var path = Path.Combine(dir.Path, f.RelativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllBytes(path, f.Content.Span);
        }
        var loaded = CompiledScene.Load(dir.Path);
        Assert.Equal(report.Placed.Count, loaded.Objects.Count);
        Assert.Equal(report.Placed.Select(p => report.For(p.Object)!.Model), loaded.Objects.Select(o => o.Model));
        Assert.Equal([GroundFloor, Cellar], loaded.Cells.Select(c => c.CellId));
        var retail = SceneCompiler.Query(report, c => c.Retail);
        var checkedProbes = 0;
        foreach (var placed in report.Placed.Select(p => p.Object))
        {
            var frame = new AcShadow.Fixtures.Collision.PartPose(placed.Frame.Position, Quaternion.Normalize(placed.Frame.Rotation), 1f);
            foreach (var p in report.For(placed)!.Probes)
            {
                var at = frame.ToEntity(p.Center);
                Assert.True(retail.Overlaps(at, p.Radius) == loaded.Overlaps(at, p.Radius), $"object {placed.Index} probe {p}");
                checkedProbes++;
            }
        }
        foreach (var cell in report.Cells)
            foreach (var p in cell.Probes)
            {
                var at = cell.Frame.ToEntity(p.Center);
                Assert.True(retail.Overlaps(at, p.Radius) == loaded.Overlaps(at, p.Radius), $"cell 0x{cell.Cell.Id:X8} probe {p}");
                checkedProbes++;
            }
        Assert.Equal(report.Totals.Positions, checkedProbes);
        using var doc = JsonDocument.Parse(files.Single(f => f.RelativePath == "compiled-scene.json").Content);
        Assert.Equal("acshadow.compiled-scene/1", doc.RootElement.GetProperty("format").GetString());
        var errors = Schemas.SchemaValidationTests.LoadSchemas().Validate(doc.RootElement, "urn:acshadow:schema:acshadow.compiled-scene-1");
        Assert.True(errors.Count == 0, string.Join('\n', errors.Take(10)));
    }

    [Fact]
    public void The_scene_command_writes_the_compiled_scene_its_chart_and_says_what_it_chose()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("scene", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet");
        Assert.True(run.ExitCode == 0, run.Error);
        foreach (var file in new[] { "compiled-scene.json", "scene-chart.csv", "scene-chart.svg" })
            Assert.True(File.Exists(Path.Combine(dir.Path, file)), file);
        Assert.Contains("part-hulls", run.Out);
        Assert.Contains("movement: mover 0x02001100; 5 candidate model(s) walked over 1512 case(s), 0 refused for a movement false pass", run.Out);
        Assert.Contains("0 false pass, 0 false block", run.Out);
        var csv = File.ReadAllLines(Path.Combine(dir.Path, "scene-chart.csv"));
        Assert.Equal(SceneChartCsv.Header, csv[0]);
        Assert.StartsWith("landblock,,,all-retail,", csv[1]);
        Assert.StartsWith("landblock,,,compiled,", csv[2]);
        Assert.StartsWith("landblock,,,all-retail-exhaustive,", csv[3]);
        // Counted only: no time columns.
        Assert.StartsWith("landblock,,,all-retail-narrow-floor,", csv[4]);
        Assert.Contains(",,,,", csv[4]);
        // The four outdoor objects, the Setup inside the cottage, and the cottage's two cells.
        Assert.Equal(5, csv.Count(l => l.StartsWith("object,")));
        Assert.Equal(2, csv.Count(l => l.StartsWith("cell,") && l.Contains(",retail,")));
    }

    [Fact]
    public void Cells_stay_retail_because_a_solid_would_fill_the_room_and_the_object_inside_is_compiled_like_any_other()
    {
        var report = Exact.Value;
        Assert.Equal([GroundFloor, Cellar], report.Cells.Select(c => c.Cell.Id));
        foreach (var cell in report.Cells)
        {
            var bsp = Assert.IsType<AcShadow.Fixtures.Collision.CompiledBsp>(cell.Bsp);
            Assert.All(ProbeKinds.Stability, k => Assert.True(ChartProbes.Count(cell.Probes, k) > 0, $"0x{cell.Cell.Id:X8} {k}"));
            // The premise of keeping a cell's tree: the cheapest solid that holds its walls, the convex hull of
            // its own vertices, fills the middle of the room, where retail lets a mover stand.
            var vertices = bsp.Polygons.SelectMany(p => p.Vertices).Distinct().ToArray();
            var hull = AcShadow.Analysis.Fitting.ConvexHullBuilder.Build(vertices, bsp.Polygons.Select(p => new Plane(p.Normal, p.D)).ToArray());
            Assert.NotNull(hull);
            var middle = cell.Bounds.Center;
            var retail = new AcShadow.Fixtures.Collision.BspSphereQuery(bsp);
            Assert.False(retail.Overlaps(middle, 0.25f), $"0x{cell.Cell.Id:X8}: the middle of the room is free in retail");
            Assert.True(hull.Overlaps(middle, 0.25f), $"0x{cell.Cell.Id:X8}: its hull fills the room");
        }
        var inside = Assert.Single(report.Placed, p => p.CellId == GroundFloor);
        Assert.Equal(ScenePlacedBy.Cell, inside.Object.PlacedBy);
        var compiled = report.For(inside.Object)!;
        Assert.NotNull(compiled.Model);
        Assert.Equal(0, compiled.FalsePass);
        Assert.Equal(0, compiled.FalseBlock);
        Assert.Equal(report.Totals.Positions, report.Totals.Agree);
    }

    [Fact]
    public void The_loaded_compiled_scene_walks_in_through_the_cottage_door_and_down_into_the_cellar_as_retail_does()
    {
        using var dir = new TempDir();
        var report = Exact.Value;
        foreach (var f in CompiledSceneFiles.Render(report, id => AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!)))
        {
            var path = Path.Combine(dir.Path, f.RelativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllBytes(path, f.Content.Span);
        }
        var loaded = CompiledScene.Load(dir.Path);
        var retail = SceneCompiler.Query(report, c => c.Retail);
        var ground = report.Cells.Single(c => c.Cell.Id == GroundFloor).Frame;
        const float player = 0.48f;
        var walk = CottageWalk(player + 0.05f).Select(ground.ToEntity).ToArray();
        Assert.All(walk, p => Assert.False(loaded.Overlaps(p, player), $"the walk is blocked at {p}"));
        Assert.All(walk, p => Assert.False(retail.Overlaps(p, player)));
        // The same walk 0.1 m lower runs the sphere into the floors and the ramp: both answers block, and agree everywhere.
        var low = walk.Select(p => p - new Vector3(0, 0, 0.1f)).ToArray();
        Assert.Contains(low, p => loaded.Overlaps(p, player));
        Assert.All(low, p => Assert.Equal(retail.Overlaps(p, player), loaded.Overlaps(p, player)));
        Assert.Contains(low, p => loaded.TouchingCells(p, player).Contains(Cellar));
    }

    /// <summary>
    /// A walk in the ground floor's own frame, <paramref name="h"/> above what it walks on: from outside the
    /// door into the room, over the stairwell, down the ramp (normal (-0.6, 0, 0.8)) and across the cellar.
    /// </summary>
    private static IEnumerable<Vector3> CottageWalk(float h)
    {
        var rampNormal = new Vector3(-0.6f, 0, 0.8f);
        Vector3 OnRamp(float x) => new Vector3(x, 1.75f, -3f + 0.75f * (x + 1f)) + rampNormal * h;
        Vector3[] corners =
        [
            new(0, -4, h), new(0, 0, h), new(2.3f, 0, h), new(2.3f, 1.75f, h),
            OnRamp(2.3f), OnRamp(0f), new(-2, 1.75f, -3 + h), new(-2, -1, -3 + h),
        ];
        for (var i = 0; i + 1 < corners.Length; i++)
        {
            var steps = (int)MathF.Ceiling(Vector3.Distance(corners[i], corners[i + 1]) / 0.02f);
            for (var k = 0; k < steps; k++) yield return Vector3.Lerp(corners[i], corners[i + 1], k / (float)steps);
        }
        yield return corners[^1];
    }

    [Theory]
    [InlineData("--out", "x")]
    [InlineData("--landblock", "0xA9B4", "--out", "x", "--tolerance", "101")]
    [InlineData("--landblock", "0xA9B4", "--out", "x", "--mover-radius", "-1")]
    [InlineData("--landblock", "0xA9B4", "--out", "x", "--mover-radius", "big")]
    public void Bad_scene_arguments_are_one_line_and_exit_2(params string[] args)
    {
        var run = CliRun.Of(["scene", .. args]);
        Assert.Equal(2, run.ExitCode);
        Assert.Single(run.Error.Trim().Split('\n'));
    }
}
