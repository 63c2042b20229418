using AcShadow.Core.Chart.Models;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Fixtures.Collision;

namespace AcShadow.Core.Chart;

/// <summary>
/// Runs the chart: for each object, prepare every model, lay the probes (grid around everything any model
/// sees, doorway lines across the reference's footprint), ask every model about every probe, compare with
/// the first model (the reference), rank the disagreements by nearness to the boundary, and time each
/// model. Objects and models run one after another, so answers are the same on any machine and timings are
/// not disturbed by each other.
/// </summary>
public static class ChartRunner
{
    public const string ModelFailed = "model-failed";

    /// <summary>Charts every subject; <paramref name="progress"/> hears (objects done, objects in all) after each.</summary>
    public static ChartReport Run(IEnumerable<ChartSubject> subjects, ChartOptions options, IReadOnlyList<IShapeModel>? models = null, IQueryTimer? timer = null, Action<int, int>? progress = null)
    {
        if (options.Problem() is { } problem) throw new ArgumentException(problem, nameof(options));
        models ??= ShapeModels.All;
        if (models.Count == 0) throw new ArgumentException("at least the reference model is needed", nameof(models));
        timer ??= new StopwatchQueryTimer();
        var all = subjects.ToArray();
        var charts = new List<ObjectChart>(all.Length);
        foreach (var subject in all)
        {
            charts.Add(Chart(subject, options, models, timer));
            progress?.Invoke(charts.Count, all.Length);
        }
        return new ChartReport(options, models.Select(m => m.Name).ToArray(), charts);
    }

    public static ObjectChart Chart(ChartSubject subject, ChartOptions options, IReadOnlyList<IShapeModel> models, IQueryTimer timer)
    {
        var prepared = models.Select(m => Prepare(m, subject)).ToArray();
        var reference = prepared[0];
        var everything = ShapeBounds.Of(prepared.SelectMany(p => p.Shapes));
        var referenceBounds = ShapeBounds.Of(reference.Shapes);
        var grid = ProbeGrid.Build(everything, options);
        var opening = DoorwayProbes.Find(referenceBounds);
        var probes = grid.Probes.Concat(DoorwayProbes.Build(opening, options)).ToArray();
        var notes = new List<string>();
        if (grid.Spacing != options.Spacing)
            notes.Add(FormattableString.Invariant($"grid coarsened from {options.Spacing} m to {grid.Spacing} m to stay under {options.MaxGridProbes} probes"));

        var referenceAnswers = Answers(reference, probes);
        var outcomes = new List<ModelOutcome>(models.Count);
        for (var m = 0; m < models.Count; m++)
        {
            var answers = m == 0 ? referenceAnswers : Answers(prepared[m], probes);
            outcomes.Add(Compare(models[m].Name, prepared[m], reference, probes, referenceAnswers, answers, options, timer));
        }
        var cheapest = CheapestExact(outcomes);
        return new ObjectChart(subject.Setup.Id, probes, grid.Spacing, everything, opening, referenceAnswers, outcomes, cheapest, notes);
    }

    /// <summary>Medians within this factor of the fastest exact model's count as the same cost (timing noise).</summary>
    public const double CostTieFactor = 1.15;

    /// <summary>
    /// The exact model with the lowest median time; models within <see cref="CostTieFactor"/> of it are a
    /// tie, settled by model order (the reference first), so run-to-run timing noise cannot flip the answer
    /// between two models that cost the same.
    /// </summary>
    internal static string CheapestExact(IReadOnlyList<ModelOutcome> outcomes)
    {
        var exact = outcomes.Where(o => o.Exact).ToArray();
        if (exact.Length == 0) return "";
        var fastest = exact.Min(o => o.Timing.MedianNs);
        return exact.First(o => o.Timing.MedianNs <= fastest * CostTieFactor).Model;
    }

    private static PreparedModel Prepare(IShapeModel model, ChartSubject subject)
    {
        try
        {
            return model.Prepare(subject);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // A model that cannot prepare blocks nothing; the chart goes on and says why.
            return new PreparedModel(new NothingCollides(), [], [new Diagnostic(ModelFailed, $"{model.Name} could not prepare Setup 0x{subject.Setup.Id:X8}: {e.Message}")]);
        }
    }

    private static bool[] Answers(PreparedModel model, Probe[] probes)
    {
        var answers = new bool[probes.Length];
        for (var i = 0; i < probes.Length; i++) answers[i] = model.Overlaps(probes[i].Center, probes[i].Radius);
        return answers;
    }

    private static ModelOutcome Compare(string name, PreparedModel model, PreparedModel reference, Probe[] probes, bool[] expected, bool[] answers,
        ChartOptions options, IQueryTimer timer)
    {
        int agree = 0, falsePass = 0, falseBlock = 0, doorway = 0, doorPass = 0, doorBlock = 0;
        var disagreements = new List<Disagreement>();
        for (var i = 0; i < probes.Length; i++)
        {
            var isDoor = probes[i].Kind == ProbeKind.Doorway;
            if (isDoor) doorway++;
            if (answers[i] == expected[i]) { agree++; continue; }
            var pass = expected[i];
            if (pass) { falsePass++; if (isDoor) doorPass++; }
            else { falseBlock++; if (isDoor) doorBlock++; }
            var p = probes[i];
            disagreements.Add(new Disagreement(i, p, pass, BoundaryGap.Of(reference.Shapes, p.Center, p.Radius), BoundaryGap.Of(model.Shapes, p.Center, p.Radius)));
        }
        var nearest = disagreements.OrderBy(d => d.Nearness).ThenBy(d => d.ProbeIndex).Take(options.FailuresPerModel).ToArray();
        var timing = timer.Measure(name, model, probes, options);
        return new ModelOutcome(name, model.Shapes.Count, answers, agree, falsePass, falseBlock, doorway, doorPass, doorBlock, timing, nearest, model.Diagnostics);
    }

    private sealed class NothingCollides : ISphereOverlap
    {
        public bool Overlaps(System.Numerics.Vector3 center, float radius) => false;
    }
}
