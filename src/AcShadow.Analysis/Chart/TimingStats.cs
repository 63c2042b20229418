namespace AcShadow.Analysis.Chart;

/// <summary>
/// Time per query in nanoseconds: median, 10th and 90th percentile over the timed batches (each batch
/// one pass over the timing sample, divided by its size). A measurement: it varies run to run.
/// </summary>
public sealed record TimingStats(double MedianNs, double P10Ns, double P90Ns, IReadOnlyList<double> BatchNs)
{
    public static TimingStats Of(IReadOnlyList<double> batchNs)
    {
        if (batchNs.Count == 0) return new TimingStats(double.NaN, double.NaN, double.NaN, []);
        var sorted = batchNs.Order().ToArray();
        return new TimingStats(Percentile(sorted, 0.5), Percentile(sorted, 0.1), Percentile(sorted, 0.9), batchNs);
    }

    /// <summary>Nearest rank on a sorted list: the value at round(p·(n−1)).</summary>
    public static double Percentile(IReadOnlyList<double> sorted, double p) =>
        sorted.Count == 0 ? double.NaN : sorted[(int)Math.Round(p * (sorted.Count - 1), MidpointRounding.AwayFromZero)];
}
