using System.Collections.Concurrent;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Dat;

/// <summary>
/// <see cref="IDatSource"/> over a <see cref="DatArchive"/>: decodes objects on demand and caches them,
/// so a GfxObj shared by many Setups is decoded once. Safe to use from many threads.
/// </summary>
public sealed class DatDatabase : IDatSource, IDisposable
{
    private readonly DatArchive _archive;
    private readonly ConcurrentDictionary<uint, Lazy<object?>> _cache = new();

    public DatDatabase(DatArchive archive)
    {
        _archive = archive;
        Info = new DatSourceInfo(archive.Name, archive.Length, archive.Header.Kind, archive.MaxIteration, archive.Header.BlockSize);
    }

    public static DatDatabase Open(Stream stream, string name) => new(DatArchive.Open(stream, name));

    public DatSourceInfo Info { get; }
    public DatArchive Archive => _archive;

    public Setup? ReadSetup(uint id) => Decode(id, DatObjectKind.Setup, Setup.Read, s => s.Id);
    public GfxObj? ReadGfxObj(uint id) => Decode(id, DatObjectKind.GfxObj, GfxObj.Read, g => g.Id);
    public LandBlockInfo? ReadLandBlockInfo(uint id) => Decode(id, DatObjectKind.LandBlockInfo, LandBlockInfo.Read, l => l.Id);

    public IReadOnlyList<uint> ListIds(DatObjectKind kind) =>
        _archive.Entries.Where(e => kind.Contains(e.Id)).Select(e => e.Id).ToArray();

    private T? Decode<T>(uint id, DatObjectKind kind, Func<DatBinaryReader, T> read, Func<T, uint> idOf) where T : class
    {
        if (!kind.Contains(id)) return null;
        var lazy = _cache.GetOrAdd(id, key => new Lazy<object?>(() =>
        {
            // The IDatSource boundary: whatever damaged bytes make the chain walk or a decoder throw
            // (bounds, overflow, end of stream, a bad tag, a cycle) leaves here as one "corrupt dat" naming the object.
            try
            {
                var bytes = _archive.ReadObjectBytesUnnamed(key);
                if (bytes is null) return null;
                var value = read(new DatBinaryReader(bytes));
                // Every object starts with its own id: a mismatch means the directory points at the wrong bytes.
                if (idOf(value) != key) throw new DatFormatException($"the object's bytes carry id 0x{idOf(value):X8}");
                return value;
            }
            catch (Exception e) when (DatArchive.IsReadFailure(e))
            {
                throw DatFormatException.CorruptObject($"{kind} 0x{key:X8} in {_archive.Name}", key, e);
            }
        }, LazyThreadSafetyMode.ExecutionAndPublication));
        return (T?)lazy.Value;
    }

    public void Dispose() => _archive.Dispose();
}
