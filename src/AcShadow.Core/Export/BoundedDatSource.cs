using System.Collections.Concurrent;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Export;

/// <summary>
/// <see cref="IDatSource"/> over a <see cref="DatArchive"/> that keeps at most <see cref="Capacity"/>
/// decoded objects (oldest dropped first), so a batch over a whole dat holds a working set, not the dat:
/// a GfxObj shared by neighbouring Setups is still decoded once while it is in use. Thread-safe; the
/// archive's reads are serialised by the archive itself.
/// </summary>
public sealed class BoundedDatSource : IDatSource
{
    private readonly DatArchive _archive;
    private readonly ConcurrentDictionary<uint, Lazy<object?>> _cache = new();
    private readonly ConcurrentQueue<uint> _order = new();

    public BoundedDatSource(DatArchive archive, DatSourceInfo info, int capacity = 4096)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 1);
        _archive = archive;
        Info = info;
        Capacity = capacity;
    }

    public int Capacity { get; }
    public DatSourceInfo Info { get; }

    public Setup? ReadSetup(uint id) => Decode(id, DatObjectKind.Setup, Setup.Read, s => s.Id);
    public GfxObj? ReadGfxObj(uint id) => Decode(id, DatObjectKind.GfxObj, GfxObj.Read, g => g.Id);
    public LandBlockInfo? ReadLandBlockInfo(uint id) => Decode(id, DatObjectKind.LandBlockInfo, LandBlockInfo.Read, l => l.Id);

    public IReadOnlyList<uint> ListIds(DatObjectKind kind) =>
        _archive.Entries.Where(e => kind.Contains(e.Id)).Select(e => e.Id).ToArray();

    private T? Decode<T>(uint id, DatObjectKind kind, Func<DatBinaryReader, T> read, Func<T, uint> idOf) where T : class
    {
        if (!kind.Contains(id)) return null;
        var created = new Lazy<object?>(() =>
        {
            var bytes = _archive.ReadObjectBytes(id);
            if (bytes is null) return null;
            var what = $"{kind} 0x{id:X8} in {_archive.Name}";
            var value = read(new DatBinaryReader(bytes, what));
            // As DatDatabase: every object starts with its own id; a mismatch means the directory is wrong.
            if (idOf(value) != id) throw new DatFormatException($"{what}: the object's bytes carry id 0x{idOf(value):X8}");
            return value;
        }, LazyThreadSafetyMode.ExecutionAndPublication);
        var lazy = _cache.GetOrAdd(id, created);
        if (ReferenceEquals(lazy, created))
        {
            _order.Enqueue(id);
            while (_cache.Count > Capacity && _order.TryDequeue(out var oldest)) _cache.TryRemove(oldest, out _);
        }
        return (T?)lazy.Value;
    }
}
