using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Runs the chart: for each object, prepare every model, lay the probes (grid around everything any model
/// sees, doorway lines across the reference's footprint, stability probes on its boundary: <see cref="ChartProbes"/>), ask every model about every probe, compare with
/// the first model (the reference), rank the disagreements by nearness to the boundary, and time each
/// model. Objects and models run one after another, so answers are the same on any machine and timings are
/// not disturbed by each other.
/// </summary>
internal static class ChartRunner
{
    /// <summary>The code of a model that failed to prepare an object (<see cref="ModelDiagnosticCodes.ModelFailed"/>).</summary>
    public const string ModelFailed = ModelDiagnosticCodes.ModelFailed;

    /// <summary>
    /// Charts <paramref name="count"/> subjects, made one at a time by <paramref name="subjectAt"/> (null: skipped),
    /// handing each chart to <paramref name="finished"/> in subject order as soon as it and those before it are
    /// done, and keeping only the totals: memory does not grow with the number of objects. With
    /// <paramref name="jobs"/> above 1, objects are charted side by side (answers are the same; times are
    /// measured while other objects run, so they are noisier).
    /// </summary>
    public static ChartTally Stream(int count, Func<int, ChartSubject?> subjectAt, ChartOptions options, Action<ObjectChart> finished,
        IReadOnlyList<IShapeModel>? models = null, IQueryTimer? timer = null, Action<int, int>? progress = null, int jobs = 1,
        CancellationToken cancellation = default, MovementChartOptions? movement = null, ITransitionTimer? transitionTimer = null)
    {
        if (options.Problem() is { } problem) throw new ArgumentException(problem, nameof(options));
        models ??= ShapeModels.All;
        if (models.Count == 0) throw new ArgumentException("at least the reference model is needed", nameof(models));
        ArgumentOutOfRangeException.ThrowIfLessThan(jobs, 1);
        timer ??= new StopwatchQueryTimer();
        transitionTimer ??= new StopwatchTransitionTimer();
        ObjectChart ChartOf(ChartSubject subject)
        {
            var chart = Chart(subject, options, models, timer, cancellation);
            return movement is null ? chart : chart with { Movement = MovementChartRunner.Chart(subject, movement, models, transitionTimer, cancellation) };
        }
        var tally = new ChartTally(models.Select(m => m.Name).ToArray());
        var done = 0;
        void Deliver(ObjectChart? chart)
        {
            if (chart is not null)
            {
                tally.Add(chart);
                finished(chart);
            }
            progress?.Invoke(++done, count);
        }
        if (jobs == 1)
        {
            for (var i = 0; i < count; i++)
            {
                cancellation.ThrowIfCancellationRequested();
                Deliver(subjectAt(i) is { } subject ? ChartOf(subject) : null);
            }
            return tally;
        }
        // Side by side, delivered in order: a worker more than a few objects ahead of the next one to
        // deliver waits, so finished-but-undelivered charts stay few.
        var ready = new Dictionary<int, ObjectChart?>();
        var next = 0;
        var claimed = -1;
        var gate = new object();
        var window = jobs * 2;
        Parallel.For(0, jobs, new ParallelOptions { MaxDegreeOfParallelism = jobs, CancellationToken = cancellation }, _ =>
        {
            while (true)
            {
                int i;
                lock (gate)
                {
                    while (claimed + 1 - next >= window && !cancellation.IsCancellationRequested) Monitor.Wait(gate, 100);
                    cancellation.ThrowIfCancellationRequested();
                    i = ++claimed;
                }
                if (i >= count) return;
                var chart = subjectAt(i) is { } subject ? ChartOf(subject) : null;
                lock (gate)
                {
                    ready[i] = chart;
                    while (ready.Remove(next, out var deliverable))
                    {
                        Deliver(deliverable);
                        next++;
                    }
                    Monitor.PulseAll(gate);
                }
            }
        });
        return tally;
    }

    /// <summary>
    /// Charts one object by probes. <paramref name="cancellation"/> is heard between models, so Ctrl-C on a huge object
    /// waits for one model's answers and timing, not the whole object; nothing of a cancelled object is kept.
    /// </summary>
    public static ObjectChart Chart(ChartSubject subject, ChartOptions options, IReadOnlyList<IShapeModel> models, IQueryTimer timer,
        CancellationToken cancellation = default)
    {
        var prepared = models.Select(m => Prepare(m, subject)).ToArray();
        var reference = prepared[0];
        var laid = ChartProbes.Lay(reference, prepared, options);
        var probes = laid.Probes;

        var referenceAnswers = Answers(reference, probes);
        var referenceGaps = new GapCache(reference.Shapes, probes);
        var outcomes = new List<ModelOutcome>(models.Count);
        for (var m = 0; m < models.Count; m++)
        {
            cancellation.ThrowIfCancellationRequested();
            var answers = m == 0 ? referenceAnswers : Answers(prepared[m], probes);
            outcomes.Add(Compare(models[m].Name, prepared[m], referenceGaps, probes, referenceAnswers, answers, options, timer));
        }
        var cheapest = CheapestExact(outcomes);
        return new ObjectChart(subject.Setup.Id, probes, laid.GridSpacing, laid.Bounds, laid.Doorway, referenceAnswers, outcomes, cheapest, laid.Notes);
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

    internal static PreparedModel Prepare(IShapeModel model, ChartSubject subject) => ModelPreparation.Prepare(model, subject);

    internal static bool[] Answers(PreparedModel model, Probe[] probes)
    {
        var answers = new bool[probes.Length];
        for (var i = 0; i < probes.Length; i++) answers[i] = model.Overlaps(probes[i].Center, probes[i].Radius);
        return answers;
    }

    private static ModelOutcome Compare(string name, PreparedModel model, GapCache referenceGaps, Probe[] probes, bool[] expected, bool[] answers,
        ChartOptions options, IQueryTimer timer)
    {
        int agree = 0, falsePass = 0, falseBlock = 0, doorway = 0, doorPass = 0, doorBlock = 0;
        for (var i = 0; i < probes.Length; i++)
        {
            var isDoor = probes[i].Kind == ProbeKind.Doorway;
            if (isDoor) doorway++;
            if (answers[i] == expected[i]) { agree++; continue; }
            if (expected[i]) { falsePass++; if (isDoor) doorPass++; }
            else { falseBlock++; if (isDoor) doorBlock++; }
        }
        // The nearest of each kind, so false blocks hugging the boundary (stability probes) never crowd out a false pass.
        var nearest = NearestDisagreements.Select(probes, expected, answers, referenceGaps, model.Shapes, options.FailuresPerModel);
        var timing = timer.Measure(name, model, probes, options);
        return new ModelOutcome(name, model.Shapes.Count, answers, agree, falsePass, falseBlock, doorway, doorPass, doorBlock, timing, nearest, model.Diagnostics);
    }
}
