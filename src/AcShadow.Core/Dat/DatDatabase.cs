using System.Collections.Concurrent;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Dat;

/// <summary>
/// <see cref="IDatSource"/> over a <see cref="DatArchive"/>: decodes objects on demand and caches them,
/// so a GfxObj shared by many Setups is decoded once. With a cache capacity it keeps at most that many
/// decoded objects (oldest dropped first), so a batch over a whole dat holds a working set, not the dat.
/// Safe to use from many threads: the archive reads in parallel, and each thread decodes from its own buffer.
/// Motion tables and animations are never dropped: a few hundred small objects that many Setups share,
/// each decoded once per run however many Setups ask for it.
/// </summary>
public sealed class DatDatabase : IDatSource, IDisposable
{
    private readonly DatArchive _archive;
    private readonly ConcurrentDictionary<uint, Lazy<object?>> _cache = new();
    private readonly ConcurrentQueue<uint> _order = new();
    private readonly ConcurrentDictionary<uint, Lazy<object?>> _motionCache = new();
    private readonly int? _capacity;

    public DatDatabase(DatArchive archive, int? cacheCapacity = null)
    {
        if (cacheCapacity is { } c) ArgumentOutOfRangeException.ThrowIfLessThan(c, 1);
        _archive = archive;
        _capacity = cacheCapacity;
        // Read only when something asks (a dump never does): the fallback needs the whole directory.
        _info = new Lazy<DatSourceInfo>(() =>
        {
            var (iteration, source) = DatIteration.Of(archive);
            return new DatSourceInfo(archive.Name, archive.Length, archive.Header.Kind, iteration, archive.Header.BlockSize) { IterationSource = source };
        });
    }

    private readonly Lazy<DatSourceInfo> _info;

    public static DatDatabase Open(Stream stream, string name) => new(DatArchive.Open(stream, name));

    public DatSourceInfo Info => _info.Value;
    public DatArchive Archive => _archive;

    public Setup? ReadSetup(uint id) => Decode(id, DatObjectKind.Setup, Setup.Read, s => s.Id);
    public GfxObj? ReadGfxObj(uint id) => Decode(id, DatObjectKind.GfxObj, GfxObj.Read, g => g.Id);
    public LandBlockInfo? ReadLandBlockInfo(uint id) => Decode(id, DatObjectKind.LandBlockInfo, LandBlockInfo.Read, l => l.Id);
    public MotionTable? ReadMotionTable(uint id) => Decode(id, DatObjectKind.MotionTable, MotionTable.Read, m => m.Id, _motionCache);
    public Animation? ReadAnimation(uint id) => Decode(id, DatObjectKind.Animation, Animation.Read, a => a.Id, _motionCache);

    /// <summary>How many motion tables and animations were decoded (the once-per-run guarantee is tested on it).</summary>
    public int MotionObjectsDecoded => _motionDecodes;

    private int _motionDecodes;
    public EnvCell? ReadEnvCell(uint id) => Decode(id, DatObjectKind.EnvCell, EnvCell.Read, c => c.Id);
    public CellEnvironment? ReadEnvironment(uint id) => Decode(id, DatObjectKind.Environment, CellEnvironment.Read, e => e.Id);

    public long? StoredSize(uint id) => _archive.TryGetEntry(id, out var entry) ? entry.Size : null;

    public IReadOnlyList<uint> ListIds(DatObjectKind kind) =>
        _archive.Entries.Where(e => kind.Contains(e.Id)).Select(e => e.Id).ToArray();

    private T? Decode<T>(uint id, DatObjectKind kind, Func<DatBinaryReader, T> read, Func<T, uint> idOf,
        ConcurrentDictionary<uint, Lazy<object?>>? keep = null) where T : class
    {
        if (!kind.Contains(id)) return null;
        if (keep is not null && keep.TryGetValue(id, out var kept)) return (T?)kept.Value;
        var created = new Lazy<object?>(() =>
        {
            // The IDatSource boundary: whatever damaged bytes make the chain walk or a decoder throw
            // (bounds, overflow, end of stream, a bad tag, a cycle) leaves here as one "corrupt dat" naming the object.
            var buffer = ObjectBytesBuffer.Take();
            try
            {
                var size = _archive.ReadObjectBytesUnnamed(id, ref buffer);
                if (size < 0) return null;
                if (keep is not null) Interlocked.Increment(ref _motionDecodes);
                var value = read(new DatBinaryReader(buffer.AsMemory(0, size)));
                // Every object starts with its own id: a mismatch means the directory points at the wrong bytes.
                if (idOf(value) != id) throw new DatFormatException($"the object's bytes carry id 0x{idOf(value):X8}");
                return value;
            }
            catch (Exception e) when (DatArchive.IsReadFailure(e))
            {
                throw DatFormatException.CorruptObject($"{kind} 0x{id:X8} in {_archive.Name}", id, e);
            }
            finally
            {
                ObjectBytesBuffer.Return(buffer);
            }
        }, LazyThreadSafetyMode.ExecutionAndPublication);
        if (keep is not null) return (T?)keep.GetOrAdd(id, created).Value;
        var lazy = _cache.GetOrAdd(id, created);
        if (_capacity is { } capacity && ReferenceEquals(lazy, created))
        {
            _order.Enqueue(id);
            while (_cache.Count > capacity && _order.TryDequeue(out var oldest)) _cache.TryRemove(oldest, out _);
        }
        return (T?)lazy.Value;
    }

    public void Dispose() => _archive.Dispose();
}
