using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// The Iteration object (id 0xFFFF0001) real dats carry beside the header: the dat's iteration (the patch
/// level a client compares with the server's) and the runs of iterations it holds. Stored without an id:
/// <c>int current</c>, then pairs <c>int -count, int first</c> until the counts used up the current figure
/// (ACE's Iteration and DatReaderWriter's agree; DatReaderWriter writes one run from iteration 1).
/// </summary>
public sealed record IterationRecord(int Current, IReadOnlyList<IterationRun> Runs)
{
    public const uint Id = 0xFFFF0001;

    /// <summary>One run covering iterations 1 to <paramref name="current"/>, as DatReaderWriter writes it.</summary>
    public static IterationRecord Single(int current) => new(current, current > 0 ? [new IterationRun(1, current)] : []);

    public static IterationRecord Read(DatBinaryReader r)
    {
        var current = r.ReadInt32();
        var runs = new List<IterationRun>();
        long left = current;
        while (left > 0)
        {
            var negativeCount = r.ReadInt32();
            var first = r.ReadInt32();
            // The readers subtract the stored (negative) count; any other value never ends the list.
            if (negativeCount >= 0) throw new DatFormatException($"iteration run {runs.Count + 1} stores count {negativeCount}; counts are stored negative");
            runs.Add(new IterationRun(first, -negativeCount));
            left += negativeCount;
        }
        if (left < 0) throw new DatFormatException($"its runs cover {current - left} iterations, more than its current iteration {current}");
        return new IterationRecord(current, runs);
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteInt32(Current);
        foreach (var run in Runs)
        {
            w.WriteInt32(-run.Count);
            w.WriteInt32(run.First);
        }
    }
}

/// <summary><see cref="Count"/> consecutive iterations starting at <see cref="First"/>.</summary>
public readonly record struct IterationRun(int First, int Count);
