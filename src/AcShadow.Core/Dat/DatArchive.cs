using System.Buffers;
using System.Buffers.Binary;
using AcShadow.Core.Dat.Binary;
using Microsoft.Win32.SafeHandles;

namespace AcShadow.Core.Dat;

/// <summary>
/// The container layer of a dat file: header, B-tree directory and block chains. Each block starts
/// with a 4-byte offset of the next block; the rest of the block is object data. One archive may be
/// shared by many threads: a file is read with positional reads on its handle (threads read in parallel),
/// any other stream under a lock (see <see cref="ReadAt"/>).
/// Opening reads the header and the directory's root node; the rest of the directory is read as lookups
/// need it, or walked whole when something lists it (<see cref="DatDirectory"/>).
/// </summary>
public sealed class DatArchive : IDisposable
{
    /// <summary>
    /// An object up to this many blocks gets its exact buffer at once (nearly every object of a real dat);
    /// only larger ones grow as their chain is read, so growing and copying is rare.
    /// </summary>
    private const int UpFrontBlocks = 1024;

    private readonly Stream _stream;
    private readonly SafeFileHandle? _file;
    private readonly bool _ownsStream;
    private readonly object _gate = new();
    private readonly DatDirectory _directory;

    public string Name { get; }
    public DatHeader Header { get; }
    public long Length { get; }

    /// <summary>All directory entries, sorted by id (the first call walks the whole directory).</summary>
    public IReadOnlyList<DatDirectoryEntry> Entries => _directory.Entries;

    /// <summary>How the directory B-tree is built: nodes, levels, and which tool's branch fill it carries (walks it).</summary>
    public DatDirectoryShape DirectoryShape => _directory.Shape;

    /// <summary>The directory, read as lookups need it.</summary>
    public DatDirectory Directory => _directory;

    private DatArchive(Stream stream, bool ownsStream, string name)
    {
        _stream = stream;
        _file = stream is FileStream { CanSeek: true } fileStream ? fileStream.SafeFileHandle : null;
        _ownsStream = ownsStream;
        Name = name;
        Length = stream.Length;
        if (Length < DatHeader.Size)
            throw new DatFormatException($"{name}: {Length} bytes is too short for a dat header ({DatHeader.Size} bytes)");
        var headerBytes = ReadRaw(0, DatHeader.Size);
        Header = DatHeader.Read(new DatBinaryReader(headerBytes, $"{name} header"));
        _directory = new DatDirectory(this, ReadNode);
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

    public bool Contains(uint id) => TryGetEntry(id, out _);

    /// <summary>The id's entry; reads the directory nodes on its path that no lookup has read yet.</summary>
    public bool TryGetEntry(uint id, out DatDirectoryEntry entry) => _directory.TryFind(id, out entry);

    private string NodeChain(int offset) => $"{Name}: B-tree node 0x{offset:X8}'s block chain";

    /// <summary>What reading the node at <paramref name="offset"/> would refuse first when it starts outside the file; null when inside.</summary>
    internal DatFormatException? NodeOutsideTheFile(int offset) => OutsideTheFile(offset, NodeChain(offset));

    private DatFormatException? OutsideTheFile(int block, string what) =>
        block <= 0 || block + 4L > Length ? new DatFormatException($"{what} points at 0x{block:X8}, outside the {Length}-byte file") : null;

    private DatBTreeNode ReadNode(int offset)
    {
        var bytes = ReadChain(offset, DatBTreeNode.ByteSize, NodeChain(offset));
        return DatBTreeNode.Read(new DatBinaryReader(bytes, $"{Name} B-tree node 0x{offset:X8}"), offset);
    }

    /// <summary>
    /// The object's bytes with its block chain followed, or null when the dat has no such id. A damaged
    /// chain is a <see cref="DatFormatException"/> reading "corrupt dat: object 0x… in {file}: …".
    /// </summary>
    public byte[]? ReadObjectBytes(uint id)
    {
        try
        {
            return TryGetEntry(id, out var entry) ? ReadChain(entry.Offset, CheckedSize(entry), "its block chain") : null;
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
            return ReadObjectBytesUnnamed(id, ref buffer);
        }
        catch (Exception e) when (IsReadFailure(e))
        {
            throw DatFormatException.CorruptObject($"object 0x{id:X8} in {Name}", id, e);
        }
    }

    /// <summary>
    /// As <see cref="ReadObjectBytes(uint, ref byte[])"/>, but a damaged chain's message leaves naming the
    /// object to the caller.
    /// </summary>
    internal int ReadObjectBytesUnnamed(uint id, ref byte[] buffer)
    {
        if (!TryGetEntry(id, out var entry)) return -1;
        buffer = ReadChain(entry.Offset, CheckedSize(entry), "its block chain", buffer);
        return (int)entry.Size;
    }

    private static int CheckedSize(DatDirectoryEntry entry) => entry.Size <= int.MaxValue ? (int)entry.Size
        : throw new DatFormatException($"the directory gives it {entry.Size} bytes, more than any object holds");

    /// <summary>
    /// What reading damaged bytes can throw (bounds, overflow, end of stream, allocation, bad arguments);
    /// not cancellation, which is the caller's, nor thread aborts, nor a damaged directory, which is the
    /// whole dat's and must not be reported as the object a lookup was for.
    /// </summary>
    public static bool IsReadFailure(Exception e) =>
        e is not (OperationCanceledException or ThreadInterruptedException or StackOverflowException or DatDirectoryException);

    /// <summary>The largest per-entry iteration: the closest thing a dat has to a single version number.</summary>
    public int MaxIteration => Entries.Count == 0 ? 0 : Entries.Max(e => e.Iteration);

    /// <summary>
    /// Follows a block chain for <paramref name="size"/> bytes. A chain visits each block at most once (a
    /// cycle is refused, not read round again as data), and the buffer grows with the blocks actually
    /// read beyond the first <see cref="UpFrontBlocks"/>: a size a corrupt directory inflates cannot allocate
    /// more than the file holds. Blocks are read a contiguous run at a time (a chain's blocks usually follow
    /// one another), so an object costs one read, not two a block.
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
        var run = ArrayPool<byte>.Shared.Rent(Math.Min(RunBytes, ((size + payload - 1) / payload + 1) * blockSize));
        try
        {
            long runStart = 0;
            var runLength = 0;
            while (filled < size)
            {
                if (OutsideTheFile(block, what) is { } outside) throw outside;
                if (filled > 0 && !(visited ??= [start]).Add(block))
                    throw new DatFormatException($"{what} loops back to block 0x{block:X8}");
                var take = Math.Min(payload, size - filled);
                if (block + 4L + take > Length)
                    throw new DatFormatException($"{what} runs past the end of the file");
                if (block < runStart || block + 4L + take > runStart + runLength)
                {
                    // As much of the rest of the chain as the run holds, were its blocks contiguous.
                    var rest = ((long)(size - filled) + payload - 1) / payload * blockSize;
                    runLength = (int)Math.Min(Math.Min(run.Length, rest), Length - block);
                    runStart = block;
                    ReadAt(runStart, run.AsSpan(0, runLength));
                }
                var at = (int)(block - runStart);
                var next = BinaryPrimitives.ReadInt32LittleEndian(run.AsSpan(at, 4));
                if (filled + take > buffer.Length) Array.Resize(ref buffer, (int)Math.Min(size, Math.Max(2L * buffer.Length, filled + take)));
                run.AsSpan(at + 4, take).CopyTo(buffer.AsSpan(filled));
                filled += take;
                block = next & 0x7FFFFFFF;
            }
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(run);
        }
        return buffer;
    }

    private const int RunBytes = 256 * 1024;

    private byte[] ReadRaw(long offset, int count)
    {
        var bytes = new byte[count];
        ReadAt(offset, bytes);
        return bytes;
    }

    /// <summary>
    /// Positional reads: on a file, straight from its handle, so threads read in parallel (a shared stream
    /// position would serialise them and thrash the stream's buffer); any other stream under the lock.
    /// </summary>
    private void ReadAt(long offset, Span<byte> into)
    {
        if (_file is { } file)
        {
            while (into.Length > 0)
            {
                var read = RandomAccess.Read(file, into, offset);
                if (read == 0) throw new EndOfStreamException($"{Name} ends at {offset}, before the {into.Length} bytes wanted there");
                into = into[read..];
                offset += read;
            }
            return;
        }
        lock (_gate)
        {
            _stream.Position = offset;
            _stream.ReadExactly(into);
        }
    }

    /// <summary>
    /// The SHA-256 of the whole file, lowercase hex: the dat's identity for index.json and verify (a copy
    /// under another name is the same dat; a dat rewritten in place with the same size is not). Read in
    /// chunks, never held whole.
    /// </summary>
    public string ContentSha256()
    {
        using var hash = System.Security.Cryptography.IncrementalHash.CreateHash(System.Security.Cryptography.HashAlgorithmName.SHA256);
        var chunk = ArrayPool<byte>.Shared.Rent(1 << 20);
        try
        {
            for (long offset = 0; offset < Length;)
            {
                var count = (int)Math.Min(chunk.Length, Length - offset);
                ReadAt(offset, chunk.AsSpan(0, count));
                hash.AppendData(chunk, 0, count);
                offset += count;
            }
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(chunk);
        }
        return Convert.ToHexStringLower(hash.GetHashAndReset());
    }

    public void Dispose()
    {
        if (_ownsStream) _stream.Dispose();
    }
}
