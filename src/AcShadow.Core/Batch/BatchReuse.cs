using System.Buffers.Binary;
using System.Collections.Concurrent;
using System.Security.Cryptography;
using System.Text;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;

namespace AcShadow.Core.Batch;

/// <summary>
/// The incremental fast path. A Setup's fingerprint hashes the tool key and the raw dat bytes of the
/// Setup and of every GfxObj it names as a part (read, never decoded): its shadow file and its BSP dumps
/// are a function of exactly those objects. Directory entries alone (offset, size, iteration) would miss
/// a dat rewritten in place with the same layout. When the previous run recorded the same fingerprint
/// (computed over the parts it recorded: unchanged Setup bytes mean unchanged parts) and its files are
/// still on disk with their recorded sizes, the Setup is not decoded at all.
/// </summary>
/// <param name="previous">The last run's state, or null (a full run that still records fingerprints).</param>
/// <param name="objectBytes">Reads an object's raw bytes in the current dat into a buffer (see <see cref="ObjectReader"/>).</param>
/// <param name="isOnDisk">Whether a file of the previous run is still there as recorded, its content hash included.</param>
public sealed class BatchReuse(IncrementalState? previous, string toolKey, BatchReuse.ObjectReader objectBytes, Func<FileEntry, bool> isOnDisk)
{
    /// <summary>
    /// An object's raw bytes into <paramref name="buffer"/> (replaced by a larger one when too small): their
    /// length, or -1 when the dat has no such object. A buffer, not an array per object: every object a batch
    /// touches is read once more here only to be hashed.
    /// </summary>
    public delegate int ObjectReader(uint id, ref byte[] buffer);

    private readonly Dictionary<uint, IncrementalSetup> _previous =
        previous is not null && previous.Tool == toolKey ? previous.Setups.ToDictionary(s => s.Id) : [];
    /// <summary>Each object's digest, computed once however many Setups share it (32 bytes an object).</summary>
    private readonly ConcurrentDictionary<uint, byte[]> _digests = new();
    private readonly byte[] _key = Encoding.UTF8.GetBytes(toolKey);
    /// <summary>
    /// Each recorded file's check, made once however many Setups list it: a GfxObj's dump is listed by every Setup
    /// that names the part, and each check reads and hashes the whole file.
    /// </summary>
    private readonly ConcurrentDictionary<FileEntry, bool> _intact = new();

    public string Fingerprint(uint setupId, IReadOnlyList<uint> parts)
    {
        var buffer = new byte[_key.Length + (parts.Count + 1) * (4 + SHA256.HashSizeInBytes)];
        _key.CopyTo(buffer, 0);
        var length = _key.Length;
        void Add(uint id)
        {
            BinaryPrimitives.WriteUInt32LittleEndian(buffer.AsSpan(length), id);
            Digest(id).CopyTo(buffer, length + 4);
            length += 4 + SHA256.HashSizeInBytes;
        }
        Add(setupId);
        foreach (var part in parts) Add(part);
        return Convert.ToHexStringLower(SHA256.HashData(buffer.AsSpan(0, length))[..16]);
    }

    private byte[] Digest(uint id) => _digests.GetOrAdd(id, static (key, read) =>
    {
        var buffer = ObjectBytesBuffer.Take();
        try
        {
            var length = read(key, ref buffer);
            return length < 0 ? new byte[SHA256.HashSizeInBytes] : SHA256.HashData(buffer.AsSpan(0, length));
        }
        finally
        {
            ObjectBytesBuffer.Return(buffer);
        }
    }, objectBytes);

    /// <summary>The previous outcome when nothing it depends on changed and its files are intact; else null.</summary>
    public SetupOutcome? TryReuse(uint setupId)
    {
        if (!_previous.TryGetValue(setupId, out var record)) return null;
        if (Fingerprint(setupId, record.Parts) != record.Fingerprint) return null;
        foreach (var file in record.Files)
            if (!_intact.GetOrAdd(file, isOnDisk)) return null;
        return new SetupOutcome(null, record.Files, record, true);
    }
}
