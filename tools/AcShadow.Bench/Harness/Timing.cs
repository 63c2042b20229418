namespace AcShadow.Bench.Harness;

/// <summary>Repeated measurements of one thing: wall seconds and peak resident memory (MiB) per run.</summary>
public sealed record Timing(string Name, string Size, int Jobs, IReadOnlyList<double> Seconds, IReadOnlyList<double> PeakMiB, string How)
{
    public double Median => MedianOf(Seconds);
    public double Min => Seconds.Min();
    public double Max => Seconds.Max();
    /// <summary>(max − min) / median: how noisy the runs were.</summary>
    public double Spread => Median > 0 ? (Max - Min) / Median : 0;
    public double PeakMedianMiB => PeakMiB.Count == 0 ? double.NaN : MedianOf(PeakMiB);

    public static double MedianOf(IReadOnlyList<double> values)
    {
        var sorted = values.Order().ToArray();
        var mid = sorted.Length / 2;
        return sorted.Length % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    }
}
