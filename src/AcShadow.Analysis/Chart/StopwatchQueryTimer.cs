using System.Diagnostics;
using System.Numerics;
using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Analysis.Chart;

/// <summary>
/// Wall-clock timing: an evenly strided sample of the probes (at most <see cref="ChartOptions.TimingProbes"/>),
/// <see cref="ChartOptions.WarmupPasses"/> untimed passes, then <see cref="ChartOptions.TimingBatches"/>
/// timed passes with a Stopwatch. The first time a model is timed it is also run untimed for
/// <see cref="FirstWarmup"/>: .NET starts methods as quick unoptimised code and recompiles hot ones after
/// a delay, and without this the first object charted would be timed on the slow code. Single-threaded;
/// run nothing else meanwhile for clean numbers.
/// </summary>
internal sealed class StopwatchQueryTimer(TimeSpan? firstWarmup = null) : IQueryTimer
{
    // Process-wide: what the long first warm-up buys (optimised code) lasts for the process, not the run.
    private static readonly HashSet<string> Warmed = [];
    private int _sink;

    public TimeSpan FirstWarmup { get; } = firstWarmup ?? TimeSpan.FromMilliseconds(600);

    /// <summary>Hits seen while timing; read so the queries cannot be optimised away.</summary>
    public int Sink => _sink;

    public TimingStats Measure(string modelName, PreparedModel model, IReadOnlyList<Probe> probes, ChartOptions options)
    {
        if (probes.Count == 0) return TimingStats.Of([]);
        var n = Math.Min(options.TimingProbes, probes.Count);
        var centers = new Vector3[n];
        var radii = new float[n];
        for (var i = 0; i < n; i++)
        {
            var p = probes[(int)((long)i * probes.Count / n)];
            centers[i] = p.Center;
            radii[i] = p.Radius;
        }
        for (var w = 0; w < options.WarmupPasses; w++) _sink += Pass(model, centers, radii);
        bool first;
        lock (Warmed) first = Warmed.Add(modelName);
        if (first)
        {
            var warm = Stopwatch.StartNew();
            while (warm.Elapsed < FirstWarmup) _sink += Pass(model, centers, radii);
        }
        var batches = new double[options.TimingBatches];
        var watch = new Stopwatch();
        for (var b = 0; b < batches.Length; b++)
        {
            watch.Restart();
            _sink += Pass(model, centers, radii);
            watch.Stop();
            batches[b] = watch.Elapsed.TotalNanoseconds / n;
        }
        return TimingStats.Of(batches);
    }

    private static int Pass(PreparedModel model, Vector3[] centers, float[] radii)
    {
        var hits = 0;
        for (var i = 0; i < centers.Length; i++)
            if (model.Overlaps(centers[i], radii[i])) hits++;
        return hits;
    }
}
