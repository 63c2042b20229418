namespace AcShadow.Analysis.Doctor;

/// <summary>
/// How often one thing a check looks for was met, in how many objects, and the smallest object ids
/// that showed it (at most <see cref="MaxExamples"/>), so the examples do not depend on which thread
/// met which object first. Safe to add to from many threads.
/// </summary>
public sealed class Finding
{
    public const int MaxExamples = 20;

    private readonly SortedSet<uint> _examples = [];
    private long _occurrences;
    private long _objects;

    /// <summary>Occurrences (nodes, parts, hooks …) over all objects.</summary>
    public long Occurrences => Interlocked.Read(ref _occurrences);

    /// <summary>Distinct objects with at least one occurrence.</summary>
    public long Objects => Interlocked.Read(ref _objects);

    /// <summary>The smallest ids of objects with an occurrence, ascending.</summary>
    public IReadOnlyList<uint> Examples
    {
        get
        {
            lock (_examples) return [.. _examples];
        }
    }

    /// <summary>Records <paramref name="occurrences"/> (≥ 1) in object <paramref name="id"/>; call once per object.</summary>
    public void Add(uint id, long occurrences = 1)
    {
        if (occurrences <= 0) return;
        Interlocked.Add(ref _occurrences, occurrences);
        Interlocked.Increment(ref _objects);
        lock (_examples)
        {
            if (_examples.Count == MaxExamples && id > _examples.Max) return;
            _examples.Add(id);
            if (_examples.Count > MaxExamples) _examples.Remove(_examples.Max);
        }
    }
}
