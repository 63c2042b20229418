using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Core.Chart;
using AcShadow.Core.Chart.Models;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Core.Scenes.Compile;

/// <summary>
/// Compiles a landblock: every distinct placed object gets the first model of <see cref="ModelLadder"/>
/// that qualifies (<see cref="SceneCompileOptions.Accepts"/>) on the chart's probes — grid, doorway lines
/// and stability probes for every mover radius — then the chosen model and retail are timed with the
/// chart's timer, and the whole scene is asked at every probe with every object as retail and as
/// compiled (<see cref="SceneTotals"/>). Objects one after another, so answers are the same on every
/// machine and timings do not disturb each other.
/// </summary>
public static class SceneCompiler
{
    public static CompiledSceneReport Compile(LandblockScene scene, ChartSubjects subjects, SceneCompileOptions options, IQueryTimer timer, Action<int, int>? progress = null)
    {
        if (options.Problem() is { } problem) throw new ArgumentException(problem, nameof(options));
        var distinct = scene.Objects.Select(o => (o.Kind, o.Id)).Distinct().ToArray();
        var compiled = new Dictionary<(SceneObjectKind, uint), ObjectCompilation>();
        foreach (var key in distinct)
        {
            compiled[key] = CompileOne(key.Kind, key.Id, subjects, options, timer);
            progress?.Invoke(compiled.Count, distinct.Length);
        }
        var totals = Totals(scene, compiled, options, timer);
        return new CompiledSceneReport(options, scene, compiled, totals);
    }

    public static ObjectCompilation CompileOne(SceneObjectKind kind, uint id, ChartSubjects subjects, SceneCompileOptions options, IQueryTimer timer)
    {
        ChartSubject? subject;
        string? why;
        try
        {
            (subject, why) = kind switch
            {
                SceneObjectKind.Setup => (subjects.For(id, options.EntityScale), "not in the dat"),
                SceneObjectKind.GfxObj => (subjects.ForBareGfxObj(id, options.EntityScale), "not in the dat"),
                _ => (null, $"neither a Setup ({DatObjectKind.Setup.RangeText()}) nor a GfxObj ({DatObjectKind.GfxObj.RangeText()})"),
            };
        }
        catch (DatFormatException e)
        {
            (subject, why) = (null, $"unreadable: {e.Message}");
        }
        if (subject is null)
            return Unresolved(kind, id, null, [new Diagnostic("unresolved", $"{JsonIds.Format(id)}: {why}")]);
        return Compile(subject, kind, options, timer);
    }

    /// <summary>One object: the ladder on its probes, the chosen model and retail timed.</summary>
    public static ObjectCompilation Compile(ChartSubject subject, SceneObjectKind kind, SceneCompileOptions options, IQueryTimer timer)
    {
        var chart = options.Chart;
        var ladder = ModelLadder.Models;
        var prepared = ladder.Select(m => ChartRunner.Prepare(m, subject)).ToArray();
        var retail = prepared[^1];
        if (retail.Shapes.Count == 0)
            return Unresolved(kind, subject.Setup.Id, ObjectCompilation.Nothing, retail.Diagnostics) with { Retail = retail };
        var laid = ChartProbes.Lay(retail, prepared, chart);
        var probes = laid.Probes;
        var expected = ChartRunner.Answers(retail, probes);
        var candidates = new List<CandidateOutcome>();
        var chosen = prepared.Length - 1;
        var chosenAnswers = expected;
        for (var m = 0; m < prepared.Length; m++)
        {
            var answers = m == prepared.Length - 1 ? expected : ChartRunner.Answers(prepared[m], probes);
            int falsePass = 0, falseBlock = 0;
            for (var i = 0; i < probes.Length; i++)
            {
                if (answers[i] == expected[i]) continue;
                if (expected[i]) falsePass++; else falseBlock++;
            }
            // A model with no shapes for an object that has some is no model of it.
            var accepted = prepared[m].Shapes.Count > 0 && options.Accepts(falsePass, falseBlock, probes.Length);
            candidates.Add(new CandidateOutcome(ladder[m].Name, prepared[m].Shapes.Count, falsePass, falseBlock, accepted));
            if (!accepted) continue;
            chosen = m;
            chosenAnswers = answers;
            break;
        }
        var retailTiming = timer.Measure(ModelLadder.Retail, retail, probes, chart);
        var chosenTiming = chosen == prepared.Length - 1 ? retailTiming : timer.Measure(ladder[chosen].Name, prepared[chosen], probes, chart);
        return new ObjectCompilation(subject.Setup.Id, kind, ladder[chosen].Name, prepared[chosen], retail, probes, expected, chosenAnswers,
            candidates, chosenTiming, retailTiming, laid.Bounds, [.. retail.Diagnostics, .. chosen == prepared.Length - 1 ? [] : prepared[chosen].Diagnostics]);
    }

    private static ObjectCompilation Unresolved(SceneObjectKind kind, uint id, string? model, IReadOnlyList<Diagnostic> diagnostics) =>
        new(id, kind, model, null, null, [], [], [], [], TimingStats.Of([]), TimingStats.Of([]), Bounds.Empty, diagnostics);

    /// <summary>The scene asked as a whole at every placed object's probes, all-retail against compiled.</summary>
    private static SceneTotals Totals(LandblockScene scene, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled, SceneCompileOptions options, IQueryTimer timer)
    {
        var retail = Query(scene, compiled, c => c.Retail);
        var chosen = Query(scene, compiled, c => c.Chosen);
        var positions = new List<Probe>();
        foreach (var placed in scene.Objects)
        {
            if (compiled.GetValueOrDefault((placed.Kind, placed.Id)) is not { } c) continue;
            var frame = new PartPose(placed.Frame.Origin, Normalised(placed.Frame.Orientation), 1f);
            foreach (var p in c.Probes) positions.Add(p with { Center = frame.ToEntity(p.Center) });
        }
        int agree = 0, falsePass = 0, falseBlock = 0;
        foreach (var p in positions)
        {
            var expected = retail.Overlaps(p.Center, p.Radius);
            var answer = chosen.Overlaps(p.Center, p.Radius);
            if (expected == answer) agree++;
            else if (expected) falsePass++;
            else falseBlock++;
        }
        var retailTiming = timer.Measure("scene: every object retail", new PreparedModel(retail, [], []), positions, options.Chart);
        var compiledTiming = timer.Measure("scene: compiled", new PreparedModel(chosen, [], []), positions, options.Chart);
        int Shapes(Func<ObjectCompilation, PreparedModel?> pick) =>
            scene.Objects.Sum(o => compiled.GetValueOrDefault((o.Kind, o.Id)) is { } c && pick(c) is { } m ? m.Shapes.Count : 0);
        return new SceneTotals(positions.Count, agree, falsePass, falseBlock, retailTiming, compiledTiming, Shapes(c => c.Retail), Shapes(c => c.Chosen));
    }

    /// <summary>Every placed object with a model, in landblock space, answered by the model <paramref name="pick"/> gives.</summary>
    public static SceneQuery Query(LandblockScene scene, IReadOnlyDictionary<(SceneObjectKind, uint), ObjectCompilation> compiled, Func<ObjectCompilation, PreparedModel?> pick)
    {
        var objects = new List<PlacedQuery>();
        foreach (var placed in scene.Objects)
        {
            if (compiled.GetValueOrDefault((placed.Kind, placed.Id)) is not { } c || pick(c) is not { } model || c.Bounds.IsEmpty) continue;
            var (center, radius) = Bound(c.Bounds);
            objects.Add(new PlacedQuery(placed.Index, placed.Id, placed.Frame.Origin, placed.Frame.Orientation, model.Query, center, radius));
        }
        return new SceneQuery(objects);
    }

    /// <summary>The sphere around an entity-space box, padded so rounding never lets it reject a touching sphere.</summary>
    public static (Vector3 Center, float Radius) Bound(Bounds b)
    {
        var half = b.Size * 0.5f;
        return (b.Center, MathF.Sqrt(half.X * half.X + half.Y * half.Y + half.Z * half.Z) * 1.0001f + 1e-3f);
    }

    private static Quaternion Normalised(Quaternion q)
    {
        var length = MathF.Sqrt(q.X * q.X + q.Y * q.Y + q.Z * q.Z + q.W * q.W);
        return length > 1e-6f && float.IsFinite(length) ? new Quaternion(q.X / length, q.Y / length, q.Z / length, q.W / length) : Quaternion.Identity;
    }
}
