namespace AcShadow.Bench.Harness;

/// <summary>
/// Repeated measurements of one thing: wall seconds, peak resident memory (MiB) and CPU seconds (user +
/// system: on a busy machine it moves less than wall time) per run. <see cref="Output"/> says where the
/// workload wrote: "disk" (the work folder), "memory" (tmpfs) or "none".
/// </summary>
public sealed record Timing(string Name, string Size, int Jobs, IReadOnlyList<double> Seconds, IReadOnlyList<double> PeakMiB, IReadOnlyList<double> CpuSeconds, string How, string Output)
{
    public double Median => MedianOf(Seconds);
    public double Min => Seconds.Count == 0 ? double.NaN : Seconds.Min();
    public double Max => Seconds.Count == 0 ? double.NaN : Seconds.Max();
    /// <summary>(max − min) / median: how noisy the runs were.</summary>
    public double Spread => Median > 0 ? (Max - Min) / Median : 0;
    public double PeakMedianMiB => PeakMiB.Count == 0 ? double.NaN : MedianOf(PeakMiB);
    public double CpuMedian => CpuSeconds.Count == 0 ? double.NaN : MedianOf(CpuSeconds);

    public static double MedianOf(IReadOnlyList<double> values)
    {
        if (values.Count == 0) return double.NaN;
        var sorted = values.Order().ToArray();
        var mid = sorted.Length / 2;
        return sorted.Length % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    }
}
