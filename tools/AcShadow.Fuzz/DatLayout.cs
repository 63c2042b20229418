using AcShadow.Core.Dat;

namespace AcShadow.Fuzz;

/// <summary>
/// Where things sit in an intact dat, so mutations can aim at them: the blocks, the header's fields,
/// the B-tree nodes and directory entries, and each object's block chain (payload offset → file offset).
/// </summary>
public sealed class DatLayout
{
    /// <summary>Header fields after the magic at 0x140, each an int32: name and file offset.</summary>
    public static readonly IReadOnlyList<(string Name, int Offset)> HeaderFields =
    [
        ("magic", 0x140), ("block size", 0x144), ("file size", 0x148), ("data set", 0x14C), ("subset", 0x150),
        ("first free block", 0x154), ("last free block", 0x158), ("free block count", 0x15C), ("root offset", 0x160),
    ];

    public DatLayout(byte[] bytes)
    {
        using var archive = DatArchive.Open(new MemoryStream(bytes, writable: false), "layout.dat");
        BlockSize = archive.Header.BlockSize;
        Length = bytes.Length;
        FirstBlock = (DatHeader.Size + BlockSize - 1) / BlockSize * BlockSize;
        Objects = archive.Entries.Select(e => new ObjectChain(e.Id, e.Size, Chain(bytes, e.Offset, (int)e.Size))).ToArray();
        var nodes = new List<int>();
        CollectNodes(bytes, archive.Header.RootBlock, nodes);
        NodeChains = nodes.Select(n => Chain(bytes, n, DatBTreeNode.ByteSize)).ToArray();
    }

    public int BlockSize { get; }
    public int Length { get; }
    public int FirstBlock { get; }
    public int BlockCount => (Length - FirstBlock) / BlockSize;
    public int BlockStart(int index) => FirstBlock + index * BlockSize;

    public IReadOnlyList<ObjectChain> Objects { get; }

    /// <summary>The block starts of each B-tree node's chain.</summary>
    public IReadOnlyList<int[]> NodeChains { get; }

    /// <summary>The file offset of byte <paramref name="payloadOffset"/> of a chain whose blocks start at <paramref name="blocks"/>.</summary>
    public int FileOffset(int[] blocks, int payloadOffset)
    {
        var per = BlockSize - 4;
        return blocks[payloadOffset / per] + 4 + payloadOffset % per;
    }

    private int[] Chain(byte[] bytes, int start, int size)
    {
        var blocks = new List<int>();
        var block = start;
        for (var filled = 0; filled < size || blocks.Count == 0; filled += BlockSize - 4)
        {
            blocks.Add(block);
            block = BitConverter.ToInt32(bytes, block) & 0x7FFFFFFF;
            if (size == 0) break;
        }
        return blocks.ToArray();
    }

    private void CollectNodes(byte[] bytes, int offset, List<int> nodes)
    {
        if (offset == 0) return;
        nodes.Add(offset);
        var chain = Chain(bytes, offset, DatBTreeNode.ByteSize);
        var first = BitConverter.ToInt32(bytes, FileOffset(chain, 0));
        if (first == 0) return;
        var count = BitConverter.ToInt32(bytes, FileOffset(chain, DatBTreeNode.MaxBranches * 4));
        for (var i = 0; i <= count; i++) CollectNodes(bytes, BitConverter.ToInt32(bytes, FileOffset(chain, i * 4)), nodes);
    }

    public sealed record ObjectChain(uint Id, uint Size, int[] Blocks);
}
