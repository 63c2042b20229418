namespace AcShadow.Analysis.Doctor;

/// <summary>A count many threads add to.</summary>
public sealed class Counter
{
    private long _value;

    public long Value => Interlocked.Read(ref _value);

    public void Add(long n = 1) => Interlocked.Add(ref _value, n);
}
