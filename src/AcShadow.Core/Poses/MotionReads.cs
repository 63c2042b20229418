using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Poses;

/// <summary>
/// A motion source that remembers every id it was asked for, present or not: what one Setup's pose
/// depends on, so an incremental batch re-exports the Setup when any of those objects changes.
/// </summary>
public sealed class MotionReads(IMotionSource source) : IMotionSource
{
    private readonly SortedSet<uint> _ids = [];

    public IReadOnlyCollection<uint> Ids => _ids;

    public MotionTable? ReadMotionTable(uint id)
    {
        _ids.Add(id);
        return source.ReadMotionTable(id);
    }

    public Animation? ReadAnimation(uint id)
    {
        _ids.Add(id);
        return source.ReadAnimation(id);
    }
}
