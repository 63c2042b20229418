using System.Buffers.Binary;

namespace AcShadow.Core.Dat;

/// <summary>
/// The container layer of a dat file: header, B-tree directory and block chains. Each block starts
/// with a 4-byte offset of the next block; the rest of the block is object data. Reads are serialised
/// on the stream the caller hands in, so one archive may be shared by many threads.
/// </summary>
public sealed class DatArchive : IDisposable
{
    /// <summary>
    /// An object up to this many blocks gets its exact buffer at once (nearly every object of a real dat);
    /// only larger ones grow as their chain is read, so growing and copying is rare.
    /// </summary>
    private const int UpFrontBlocks = 1024;

    private readonly Stream _stream;
    private readonly bool _ownsStream;
    private readonly object _gate = new();
    private readonly DatDirectoryEntry[] _entries;
    private readonly Dictionary<uint, int> _indexById;

    public string Name { get; }
    public DatHeader Header { get; }
    public long Length { get; }

    /// <summary>All directory entries, sorted by id.</summary>
    public IReadOnlyList<DatDirectoryEntry> Entries => _entries;

    private DatArchive(Stream stream, bool ownsStream, string name)
    {
        _stream = stream;
        _ownsStream = ownsStream;
        Name = name;
        Length = stream.Length;
        if (Length < DatHeader.Size)
            throw new DatFormatException($"{name}: {Length} bytes is too short for a dat header ({DatHeader.Size} bytes)");
        var headerBytes = ReadRaw(0, DatHeader.Size);
        Header = DatHeader.Read(new DatBinaryReader(headerBytes, $"{name} header"));
        _entries = ReadDirectory();
        _indexById = new Dictionary<uint, int>(_entries.Length);
        for (var i = 0; i < _entries.Length; i++) _indexById[_entries[i].Id] = i;
    }

    /// <summary>Opens a dat from a readable, seekable stream.</summary>
    public static DatArchive Open(Stream stream, string name, bool ownsStream = true)
    {
        if (!stream.CanRead || !stream.CanSeek)
            throw new ArgumentException("a dat stream must be readable and seekable", nameof(stream));
        try
        {
            return new DatArchive(stream, ownsStream, name);
        }
        catch (Exception e)
        {
            if (ownsStream) stream.Dispose();
            if (e is DatFormatException || !IsReadFailure(e)) throw;
            throw new DatFormatException($"{name}: the header or directory cannot be read ({e.GetType().Name}: {e.Message})");
        }
    }

    public bool Contains(uint id) => _indexById.ContainsKey(id);

    public bool TryGetEntry(uint id, out DatDirectoryEntry entry)
    {
        if (_indexById.TryGetValue(id, out var i)) { entry = _entries[i]; return true; }
        entry = default;
        return false;
    }

    /// <summary>
    /// The object's bytes with its block chain followed, or null when the dat has no such id. A damaged
    /// chain is a <see cref="DatFormatException"/> reading "corrupt dat: object 0x… in {file}: …".
    /// </summary>
    public byte[]? ReadObjectBytes(uint id)
    {
        try
        {
            return ReadObjectBytesUnnamed(id);
        }
        catch (Exception e) when (IsReadFailure(e))
        {
            throw DatFormatException.CorruptObject($"object 0x{id:X8} in {Name}", id, e);
        }
    }

    /// <summary>
    /// As <see cref="ReadObjectBytes(uint)"/>, into <paramref name="buffer"/> (replaced by a larger one when too
    /// small): the object's length, or -1 when the dat has no such id. For callers that only look at each
    /// object's bytes once (fingerprints), so they reuse one buffer instead of an array per object.
    /// </summary>
    public int ReadObjectBytes(uint id, ref byte[] buffer)
    {
        try
        {
            if (!TryGetEntry(id, out var entry)) return -1;
            buffer = ReadChain(entry.Offset, CheckedSize(entry), "its block chain", buffer);
            return (int)entry.Size;
        }
        catch (Exception e) when (IsReadFailure(e))
        {
            throw DatFormatException.CorruptObject($"object 0x{id:X8} in {Name}", id, e);
        }
    }

    /// <summary>As <see cref="ReadObjectBytes(uint)"/>, but a damaged chain's message leaves naming the object to the caller.</summary>
    internal byte[]? ReadObjectBytesUnnamed(uint id)
    {
        if (!TryGetEntry(id, out var entry)) return null;
        return ReadChain(entry.Offset, CheckedSize(entry), "its block chain");
    }

    private static int CheckedSize(DatDirectoryEntry entry) => entry.Size <= int.MaxValue ? (int)entry.Size
        : throw new DatFormatException($"the directory gives it {entry.Size} bytes, more than any object holds");

    /// <summary>
    /// What reading damaged bytes can throw (bounds, overflow, end of stream, allocation, bad arguments);
    /// not cancellation, which is the caller's, nor thread aborts.
    /// </summary>
    internal static bool IsReadFailure(Exception e) =>
        e is not (OperationCanceledException or ThreadInterruptedException or StackOverflowException);

    /// <summary>The largest per-entry iteration: the closest thing a dat has to a single version number.</summary>
    public int MaxIteration => _entries.Length == 0 ? 0 : _entries.Max(e => e.Iteration);

    private DatDirectoryEntry[] ReadDirectory()
    {
        var result = new List<DatDirectoryEntry>();
        if (Header.RootBlock == 0) return [];
        var visited = new HashSet<int>();
        Walk(Header.RootBlock, 0);
        result.Sort((a, b) => a.Id.CompareTo(b.Id));
        for (var i = 1; i < result.Count; i++)
            if (result[i].Id == result[i - 1].Id)
                throw new DatFormatException($"{Name}: the directory lists id 0x{result[i].Id:X8} twice");
        return result.ToArray();

        void Walk(int offset, int depth)
        {
            if (depth > 32) throw new DatFormatException($"{Name}: B-tree deeper than 32 levels (cycle?)");
            if (!visited.Add(offset)) throw new DatFormatException($"{Name}: B-tree node 0x{offset:X8} is reachable twice");
            var bytes = ReadChain(offset, DatBTreeNode.ByteSize, $"{Name}: B-tree node 0x{offset:X8}'s block chain");
            var node = DatBTreeNode.Read(new DatBinaryReader(bytes, $"{Name} B-tree node 0x{offset:X8}"), offset);
            result.AddRange(node.Entries);
            foreach (var child in node.Branches) Walk(child, depth + 1);
        }
    }

    /// <summary>
    /// Follows a block chain for <paramref name="size"/> bytes. A chain visits each block at most once (a
    /// cycle is refused, not read round again as data), and the buffer grows with the blocks actually
    /// read beyond the first <see cref="UpFrontBlocks"/>: a size a corrupt directory inflates cannot allocate
    /// more than the file holds.
    /// </summary>
    /// <param name="reuse">A buffer to fill when it is large enough; the result is then that buffer, longer than <paramref name="size"/>.</param>
    private byte[] ReadChain(int start, int size, string what, byte[]? reuse = null)
    {
        var blockSize = Header.BlockSize;
        var payload = blockSize - 4;
        var maxBlocks = Length / blockSize + 1;
        if (size > maxBlocks * payload)
            throw new DatFormatException($"{what} would hold {size} bytes, more than the {Length}-byte file can");
        var upFront = Math.Min(size, UpFrontBlocks * payload);
        var buffer = reuse is not null && reuse.Length >= upFront ? reuse : new byte[upFront];
        var filled = 0;
        var block = start;
        HashSet<int>? visited = null;
        Span<byte> link = stackalloc byte[4];
        lock (_gate)
        {
            while (filled < size)
            {
                if (block <= 0 || block + 4L > Length)
                    throw new DatFormatException($"{what} points at 0x{block:X8}, outside the {Length}-byte file");
                if (filled > 0 && !(visited ??= [start]).Add(block))
                    throw new DatFormatException($"{what} loops back to block 0x{block:X8}");
                ReadRawLocked(block, link);
                var next = BinaryPrimitives.ReadInt32LittleEndian(link);
                var take = Math.Min(payload, size - filled);
                if (block + 4L + take > Length)
                    throw new DatFormatException($"{what} runs past the end of the file");
                if (filled + take > buffer.Length) Array.Resize(ref buffer, (int)Math.Min(size, Math.Max(2L * buffer.Length, filled + take)));
                ReadRawLocked(block + 4, buffer.AsSpan(filled, take));
                filled += take;
                block = next & 0x7FFFFFFF;
            }
        }
        return buffer;
    }

    private byte[] ReadRaw(long offset, int count)
    {
        var bytes = new byte[count];
        lock (_gate) ReadRawLocked(offset, bytes);
        return bytes;
    }

    /// <summary>Straight into the caller's span: a chain's blocks land in the object's buffer, no array per block.</summary>
    private void ReadRawLocked(long offset, Span<byte> into)
    {
        _stream.Position = offset;
        _stream.ReadExactly(into);
    }

    public void Dispose()
    {
        if (_ownsStream) _stream.Dispose();
    }
}
