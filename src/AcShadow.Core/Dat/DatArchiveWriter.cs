using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat;

/// <summary>
/// Writes a complete dat file: header, each object in its own block chain, and a balanced B-tree
/// directory (at most 61 entries and 62 branches per node) whose root the header points at.
/// The output depends only on the inputs, so the same objects always give the same bytes.
/// </summary>
public static class DatArchiveWriter
{
    /// <param name="Fill">What the directory's unused branch slots hold: <see cref="BranchFill.Zero"/> as retail
    /// writes them, or <see cref="BranchFill.Cdcd"/> as DatReaderWriter does.</param>
    public sealed record Options(DatFileKind Kind, int BlockSize = 1024, int Iteration = 1, uint RawDate = 0, uint SubSet = 0, BranchFill Fill = BranchFill.Zero);

    public static byte[] Write(IReadOnlyDictionary<uint, byte[]> objects, Options options)
    {
        var blockSize = options.BlockSize;
        if (blockSize < 64) throw new ArgumentOutOfRangeException(nameof(options), "block size must be at least 64 bytes");
        var file = new MemoryStream();
        var firstBlock = (DatHeader.Size + blockSize - 1) / blockSize * blockSize;
        file.SetLength(firstBlock);

        var entries = new List<DatDirectoryEntry>(objects.Count);
        foreach (var (id, bytes) in objects.OrderBy(kv => kv.Key))
        {
            var offset = AppendChain(file, bytes, blockSize);
            entries.Add(new DatDirectoryEntry(0, 2, id, offset, (uint)bytes.Length, options.RawDate, options.Iteration));
        }

        if (options.Fill is not (BranchFill.Zero or BranchFill.Cdcd))
            throw new ArgumentOutOfRangeException(nameof(options), options.Fill, "a directory is written with zero or 0xCDCDCDCD branch fill");
        var root = entries.Count == 0 ? 0 : WriteTree(file, entries, HeightFor(entries.Count), blockSize, options.Fill);
        var header = new DatHeader(blockSize, (int)file.Length, options.Kind, options.SubSet, 0, 0, 0, root, 0, 1, 1, Guid.Empty, 1);
        var headerWriter = new DatBinaryWriter();
        header.Write(headerWriter);
        file.Position = 0;
        file.Write(headerWriter.ToArray());
        return file.ToArray();
    }

    private static int HeightFor(int count)
    {
        var height = 1;
        long capacity = DatBTreeNode.MaxEntries;
        while (capacity < count) { height++; capacity = capacity * DatBTreeNode.MaxBranches + DatBTreeNode.MaxEntries; }
        return height;
    }

    private static long Capacity(int height)
    {
        long capacity = DatBTreeNode.MaxEntries;
        for (var h = 1; h < height; h++) capacity = capacity * DatBTreeNode.MaxBranches + DatBTreeNode.MaxEntries;
        return capacity;
    }

    /// <summary>Children first, so a parent knows its children's offsets; every leaf sits at the same depth.</summary>
    private static int WriteTree(MemoryStream file, List<DatDirectoryEntry> entries, int height, int blockSize, BranchFill fill)
    {
        DatBTreeNode node;
        if (height == 1)
        {
            node = new DatBTreeNode([], entries);
        }
        else
        {
            var childCapacity = Capacity(height - 1);
            var n = entries.Count;
            var children = (int)Math.Max(2, (n + 1 + childCapacity) / (childCapacity + 1));
            var perChild = n - (children - 1);
            var branches = new List<int>(children);
            var separators = new List<DatDirectoryEntry>(children - 1);
            var cursor = 0;
            for (var c = 0; c < children; c++)
            {
                var take = perChild / children + (c < perChild % children ? 1 : 0);
                branches.Add(WriteTree(file, entries.GetRange(cursor, take), height - 1, blockSize, fill));
                cursor += take;
                if (c < children - 1) separators.Add(entries[cursor++]);
            }
            node = new DatBTreeNode(branches, separators);
        }
        var w = new DatBinaryWriter();
        (node with { Fill = fill }).Write(w);
        return AppendChain(file, w.ToArray(), blockSize);
    }

    private static int AppendChain(MemoryStream file, byte[] bytes, int blockSize)
    {
        var payload = blockSize - 4;
        var blocks = Math.Max(1, (bytes.Length + payload - 1) / payload);
        var start = (int)file.Length;
        var block = new byte[blockSize];
        for (var i = 0; i < blocks; i++)
        {
            Array.Clear(block);
            var next = i < blocks - 1 ? start + (i + 1) * blockSize : 0;
            BitConverter.TryWriteBytes(block.AsSpan(0, 4), next);
            var take = Math.Min(payload, bytes.Length - i * payload);
            bytes.AsSpan(i * payload, take).CopyTo(block.AsSpan(4));
            file.Position = file.Length;
            file.Write(block);
        }
        return start;
    }
}
