namespace AcShadow.Analysis.Doctor;

/// <summary>
/// Distances in units in the last place, in power-of-two buckets ("1", "2", "3-4", "5-8", … "> 2^20"), plus
/// the planes no candidate came near. Safe to add to from many threads; the buckets are fixed, so two
/// reports compare bucket by bucket.
/// </summary>
public sealed class UlpHistogram
{
    private const int PowerBuckets = 21; // 1, 2, 3-4, …, up to 2^20
    private readonly long[] _buckets = new long[PowerBuckets + 1];

    public void Add(long ulps)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(ulps, 1);
        var bucket = 0;
        while (bucket < PowerBuckets && ulps > 1L << bucket) bucket++;
        Interlocked.Increment(ref _buckets[bucket]);
    }

    /// <summary>Every bucket, empty ones included, in order.</summary>
    public IReadOnlyList<KeyValuePair<string, long>> Buckets() =>
        [.. Enumerable.Range(0, PowerBuckets + 1).Select(i => new KeyValuePair<string, long>(Label(i), Interlocked.Read(ref _buckets[i])))];

    private static string Label(int bucket) => bucket switch
    {
        0 => "1",
        1 => "2",
        PowerBuckets => $">{1L << (PowerBuckets - 1)}",
        _ => $"{(1L << (bucket - 1)) + 1}-{1L << bucket}",
    };

    /// <summary>
    /// How many floats lie between <paramref name="a"/> and <paramref name="b"/> (0 when their bits are equal):
    /// the bits read as a sign-magnitude integer and mapped onto one ordered line, so +0 and -0 are 1 apart.
    /// </summary>
    public static long Distance(float a, float b) => Math.Abs(Ordered(a) - Ordered(b));

    private static long Ordered(float f)
    {
        var bits = BitConverter.SingleToInt32Bits(f);
        return bits >= 0 ? bits : -(long)(bits & 0x7FFFFFFF) - 1;
    }
}
