using AcShadow.Analysis.Compile;
using AcShadow.Forge;
using AcShadow.Fixtures.Scenes;
using AcShadow.Tests.Chart.Movement;

namespace AcShadow.Tests.Scenes;

/// <summary>
/// `acshadow scene` with movement (what the command always does): a cheaper model is chosen only when it lets the
/// mover past nowhere retail's walk stops, and the evidence lists both the probes' and the walks' verdicts.
/// </summary>
public class SceneMovementTests
{
    internal static readonly Lazy<CompiledSceneReport> Walked = new(() =>
        SceneCompileTests.Compile(new SceneCompileOptions { Movement = SampleMovementChart.Options with { Walk = null } }));

    [Fact]
    public void Every_chosen_model_has_movement_evidence_without_a_false_pass()
    {
        var report = Walked.Value;
        foreach (var c in report.Compiled.Values.Where(c => c.Candidates.Count > 0))
        {
            var chosen = c.Candidates[^1];
            Assert.True(chosen.Accepted);
            Assert.NotNull(chosen.Movement);
            Assert.Equal(0, chosen.Movement.FalsePasses);
            Assert.True(chosen.Movement.Cases >= 224);
            // A candidate the probes already refused is not walked.
            Assert.All(c.Candidates.Where(k => k.FalsePass > 0), k => Assert.Null(k.Movement));
        }
    }

    [Fact]
    public void The_columns_hull_walks_as_its_tree_does_and_is_chosen_with_its_walks_as_evidence()
    {
        var column = Walked.Value.Compiled[(SceneObjectKind.GfxObj, SampleSpecAuthor.Column)];
        Assert.Equal("part-hulls", column.Model);
        var hull = column.Candidates[^1].Movement!;
        Assert.Equal(224, hull.Cases);
        Assert.Equal(hull.Cases - hull.Fragile, hull[Analysis.Chart.Movement.MovementVerdict.Agree]);
    }

    [Fact]
    public void A_model_the_probes_accept_but_a_walk_gets_past_retail_is_refused()
    {
        // At 100 % tolerance the probes accept any model without a false pass: part-spheres on every object.
        var tolerant = SceneCompileTests.Compile(new SceneCompileOptions { TolerancePercent = 100, Movement = SampleMovementChart.Options with { Walk = null } });
        var probesOnly = SceneCompileTests.Compile(new SceneCompileOptions { TolerancePercent = 100 });
        Assert.Contains(probesOnly.Compiled.Values, c => c.Model == "part-spheres");
        Assert.DoesNotContain(tolerant.Compiled.Values, c => c.Model == "part-spheres");
        var door = tolerant.Compiled[(SceneObjectKind.Setup, SampleSpecAuthor.DoorSetup)];
        var spheres = door.Candidates.Single(k => k.Model == "part-spheres");
        Assert.Equal(0, spheres.FalsePass);
        Assert.False(spheres.Accepted);
        Assert.True(spheres.Movement!.FalsePasses > 0);
        Assert.All(tolerant.Compiled.Values.Where(c => c.Candidates.Count > 0), c => Assert.Equal(0, c.Candidates[^1].Movement!.FalsePasses));
    }

    [Fact]
    public void The_compiled_scene_file_records_the_mover_and_each_walked_candidates_verdicts()
    {
        var json = System.Text.Json.JsonDocument.Parse(CompiledSceneWriter.Write(Walked.Value)).RootElement;
        var errors = Schemas.SchemaValidationTests.LoadSchemas().Validate(json, "urn:acshadow:schema:acshadow.compiled-scene-1");
        Assert.True(errors.Count == 0, string.Join('\n', errors.Take(10)));
        Assert.Equal(2, json.GetProperty("mover").GetProperty("spheres").GetArrayLength());
        foreach (var o in json.GetProperty("objects").EnumerateArray())
        {
            var evidence = o.GetProperty("evidence");
            if (evidence.ValueKind == System.Text.Json.JsonValueKind.Null) continue;
            var movement = evidence.GetProperty("movement");
            Assert.Equal(0, movement.GetProperty("falsePass").GetInt32() + movement.GetProperty("fragileFalsePass").GetInt32());
            Assert.Equal(movement.GetProperty("cases").GetInt32() - movement.GetProperty("fragile").GetInt32(),
                new[] { "agree", "falsePass", "falseBlock", "deflection", "stepMismatch", "standoffDrift" }.Sum(k => movement.GetProperty(k).GetInt32()));
        }
        Assert.Equal(System.Text.Json.JsonValueKind.Null, System.Text.Json.JsonDocument.Parse(CompiledSceneWriter.Write(SceneCompileTests.Exact.Value)).RootElement.GetProperty("mover").ValueKind);
    }
}
