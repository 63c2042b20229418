using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Chart;
using AcShadow.Core.Dat;
using AcShadow.Core.Scenes;
using AcShadow.Core.Scenes.Compile;
using AcShadow.Forge;
using AcShadow.Fixtures.Scenes;
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
    internal static LandblockScene SampleScene()
    {
        var cell = DatDatabase.Open(new MemoryStream(SampleDat.CellBytes!), "client_cell_1.dat");
        return LandblockScene.From(cell.ReadLandBlockInfo(SampleSpecAuthor.Landblock)!);
    }

    private static readonly Lazy<CompiledSceneReport> Exact = new(() => Compile(new SceneCompileOptions()));

    internal static CompiledSceneReport Compile(SceneCompileOptions options) =>
        SceneCompiler.Compile(SampleScene(), SampleChart.Subjects.Value, options, new FixedTimer());

    [Fact]
    public void The_compiled_sample_landblock_gives_retails_answer_everywhere_and_models_less_where_it_can()
    {
        var report = Exact.Value;
        Assert.Equal(report.Totals.Positions, report.Totals.Agree);
        Assert.True(report.Totals.Positions > 10_000);
        var models = report.Scene.Objects.ToDictionary(o => o.Id, o => report.For(o)!.Model);
        // The bare octagonal column is convex: its hull is exact.
        Assert.Equal("part-hulls", models[SampleSpecAuthor.Column]);
        // The door keeps its BSP: a jamb with its threshold is neither a box nor a hull, and the evidence says so.
        Assert.Equal("retail", models[SampleSpecAuthor.DoorSetup]);
        var door = report.Compiled[(SceneObjectKind.Setup, SampleSpecAuthor.DoorSetup)];
        Assert.Equal(ModelLadder.Names, door.Candidates.Select(c => c.Model));
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
    public void Bsp_dumps_are_written_only_for_objects_still_modelled_by_retail()
    {
        var report = Exact.Value;
        var needed = CompiledSceneWriter.BspGfxObjs(report);
        var retailParts = report.Compiled.Values.Where(c => c.Model == "retail")
            .SelectMany(c => c.Chosen!.Shapes.Select(s => s.Shape.GfxObjId!.Value)).Distinct().Order();
        Assert.Equal(retailParts, needed);
        var files = CompiledSceneFiles.Render(report, id => SampleChart.Subjects.Value.Bsps.Get(id) is null ? null
            : AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!));
        Assert.Equal(needed.Select(AcShadow.Fixtures.Json.BspFileFormat.PathFor), files.Select(f => f.RelativePath).Where(p => p.StartsWith("gfxobjs/")));
    }

    [Fact]
    public void A_tolerance_admits_false_blocks_but_never_a_false_pass()
    {
        var report = Compile(new SceneCompileOptions { TolerancePercent = 100 });
        foreach (var c in report.Compiled.Values.Where(c => c.Probes.Length > 0))
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
        Assert.Equal(files.Select(f => f.Content), CompiledSceneFiles.Render(Compile(new SceneCompileOptions()), id => AcShadow.Core.Bsp.BspExtractor.Extract(SampleChart.Subjects.Value.GfxObj(id)!)).Select(f => f.Content));
        foreach (var f in files)
        {
            var path = Path.Combine(dir.Path, f.RelativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllBytes(path, f.Content);
        }
        var loaded = CompiledScene.Load(dir.Path);
        Assert.Equal(report.Scene.Objects.Count, loaded.Objects.Count);
        Assert.Equal(report.Scene.Objects.Select(o => report.For(o)!.Model), loaded.Objects.Select(o => o.Model));
        var retail = SceneCompiler.Query(report.Scene, report.Compiled, c => c.Retail);
        var checkedProbes = 0;
        foreach (var placed in report.Scene.Objects)
        {
            var frame = new AcShadow.Fixtures.Collision.PartPose(placed.Frame.Origin, Quaternion.Normalize(placed.Frame.Orientation), 1f);
            foreach (var p in report.For(placed)!.Probes)
            {
                var at = frame.ToEntity(p.Center);
                Assert.True(retail.Overlaps(at, p.Radius) == loaded.Overlaps(at, p.Radius), $"object {placed.Index} probe {p}");
                checkedProbes++;
            }
        }
        Assert.Equal(report.Totals.Positions, checkedProbes);
        using var doc = JsonDocument.Parse(files[0].Content);
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
        Assert.Contains("0 false pass, 0 false block", run.Out);
        var csv = File.ReadAllLines(Path.Combine(dir.Path, "scene-chart.csv"));
        Assert.Equal(SceneChartCsv.Header, csv[0]);
        Assert.StartsWith("landblock,,,all-retail,", csv[1]);
        Assert.StartsWith("landblock,,,compiled,", csv[2]);
        Assert.Equal(4, csv.Count(l => l.StartsWith("object,")));
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
