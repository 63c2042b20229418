using System.Collections.Concurrent;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Core.Dat;

/// <summary>
/// A dat's directory B-tree, read as it is needed. The tree is sorted by file id (an in-order walk lists the
/// ids ascending; DatReaderWriter searches it that way, ACE's DatLoader reads it whole), so a lookup descends
/// from the root reading only the nodes on its path, searching each by halves, and keeps the nodes it read;
/// the whole tree is walked only when something lists it (<see cref="Entries"/>, <see cref="Shape"/>). A dump
/// of one Setup reads a dozen nodes instead of all of them (790 on the 47,000-file scale dat).
/// The walk checks what it always did, in the same order and with the same lines (block chains, entry counts,
/// a "no branch" where a branch is needed, a node reached twice, the depth, an id listed twice), and now that
/// the listing is in id order. A lookup makes the same checks on the nodes it reads: those, plus a branch back
/// onto its path or listed twice in its node (reachable twice), and the order its search relies on (ids
/// ascending in each node, within the range the parent gives them). Damage off a lookup's path is found by
/// the walk only (docs/dat-layer.md).
/// </summary>
public sealed class DatDirectory
{
    private const int MaxDepth = 32;

    private readonly DatArchive _archive;
    private readonly Func<int, DatBTreeNode> _readNode;
    private readonly DatBTreeNode? _root;
    private readonly Lazy<Index> _whole;
    private readonly ConcurrentDictionary<int, DatBTreeNode> _nodes = new();
    private int _nodeReads;

    /// <summary>Every entry, sorted by id, the ids alone in the same order (searched by halves), and the tree's shape.</summary>
    private sealed record Index(DatDirectoryEntry[] Entries, uint[] Ids, DatDirectoryShape Shape);

    /// <summary>Checks the header's root and reads the root node (every lookup starts there).</summary>
    internal DatDirectory(DatArchive archive, Func<int, DatBTreeNode> readNode)
    {
        _archive = archive;
        _readNode = readNode;
        _whole = new Lazy<Index>(Walk, LazyThreadSafetyMode.ExecutionAndPublication);
        var header = archive.Header;
        if (header.RootBlock == 0)
        {
            // Root 0 is an empty dat, which holds no blocks beyond the header's and the free list's; a
            // dat with more has lost its root (a damaged header), and listing nothing would pass it as empty.
            var firstBlock = (DatHeader.Size + (long)header.BlockSize - 1) / header.BlockSize * header.BlockSize;
            var unlisted = archive.Length - firstBlock - Math.Max(0L, header.FreeBlockCount) * header.BlockSize;
            if (unlisted > 0)
                throw Damage($"the header's directory root is 0 (an empty dat), but the file holds {unlisted} more bytes of blocks: the header is damaged");
            return;
        }
        _root = Node(header.RootBlock);
    }

    /// <summary>How many nodes have been read from the file so far (lookups and the walk): what a test of laziness counts.</summary>
    public int NodeReads => Volatile.Read(ref _nodeReads);

    /// <summary>All entries, sorted by id: the whole tree is walked (and checked) the first time this is asked.</summary>
    public IReadOnlyList<DatDirectoryEntry> Entries => _whole.Value.Entries;

    /// <summary>Nodes, levels and branch fill of the whole tree (walks it, as <see cref="Entries"/>).</summary>
    public DatDirectoryShape Shape => _whole.Value.Shape;

    public bool TryFind(uint id, out DatDirectoryEntry entry)
    {
        if (_whole.IsValueCreated)
        {
            var at = Array.BinarySearch(_whole.Value.Ids, id);
            entry = at >= 0 ? _whole.Value.Entries[at] : default;
            return at >= 0;
        }
        entry = default;
        if (_root is null) return false;
        var node = _root;
        var offset = _archive.Header.RootBlock;
        Span<int> path = stackalloc int[MaxDepth + 1];
        path[0] = offset;
        uint? lower = null, upper = null;
        // Checked on every lookup, not once: a few dozen comparisons per node, against a read of the file.
        CheckOrder(offset, node, lower, upper);
        CheckBranches(offset, node, path[..1]);
        for (var depth = 0; ; depth++)
        {
            var at = Search(node.Entries, id);
            if (at >= 0)
            {
                entry = node.Entries[at];
                return true;
            }
            if (node.IsLeaf) return false;
            var slot = ~at;
            var child = node.Branches[slot];
            if (depth + 1 > MaxDepth) throw Deeper();
            if (slot > 0) lower = node.Entries[slot - 1].Id;
            if (slot < node.Entries.Count) upper = node.Entries[slot].Id;
            node = Node(child);
            offset = child;
            path[depth + 1] = child;
            CheckOrder(offset, node, lower, upper);
            CheckBranches(offset, node, path[..(depth + 2)]);
        }
    }

    private static int Search(IReadOnlyList<DatDirectoryEntry> entries, uint id)
    {
        int low = 0, high = entries.Count - 1;
        while (low <= high)
        {
            var mid = low + ((high - low) >> 1);
            var at = entries[mid].Id;
            if (at == id) return mid;
            if (at < id) low = mid + 1;
            else high = mid - 1;
        }
        return ~low;
    }

    /// <summary>A branch an internal node needs; "no branch" there is damage.</summary>
    private int Branch(int offset, DatBTreeNode node, int slot)
    {
        var branch = node.Branches[slot];
        return BranchFills.IsNoBranch(branch)
            ? throw Damage($"B-tree node 0x{offset:X8} has no branch {slot} (0x{branch:X8}) though it is not a leaf")
            : branch;
    }

    /// <summary>
    /// Every branch of a node a lookup read, in the walk's order, for what the walk would refuse at this node
    /// without reading further: a "no branch" where one is needed, a branch outside the file, one back onto the
    /// path (the node itself or above it) or equal to an earlier branch of the node (reachable twice). So a
    /// lookup and a listing name the same damage in a node both read, not the first each happens to follow.
    /// </summary>
    private void CheckBranches(int offset, DatBTreeNode node, ReadOnlySpan<int> path)
    {
        for (var i = 0; i < node.Branches.Count; i++)
        {
            var branch = Branch(offset, node, i);
            if (_archive.NodeOutsideTheFile(branch) is { } outside) throw new DatDirectoryException(_archive, outside.Message, outside);
            if (path.Contains(branch)) throw ReachableTwice(branch);
            for (var j = 0; j < i; j++)
                if (node.Branches[j] == branch) throw ReachableTwice(branch);
        }
    }

    /// <summary>A node read once: a later lookup (or the walk) through it reads nothing.</summary>
    private DatBTreeNode Node(int offset) => _nodes.TryGetValue(offset, out var node) ? node : _nodes.GetOrAdd(offset, Read(offset));

    /// <summary>One node from the file: its block chain and entry count checked.</summary>
    private DatBTreeNode Read(int offset)
    {
        try
        {
            Interlocked.Increment(ref _nodeReads);
            return _readNode(offset);
        }
        catch (DatFormatException e)
        {
            throw new DatDirectoryException(_archive, e.Message, e);
        }
        catch (Exception e) when (DatArchive.IsReadFailure(e))
        {
            throw Damage($"the header or directory cannot be read ({e.GetType().Name}: {e.Message})", e);
        }
    }

    /// <summary>
    /// What a lookup's binary search relies on, for a node on its path: ids ascending within it and inside the
    /// range its parent gives it (an id equal to a bound is listed twice). The walk checks the same on the whole
    /// listing once every node is read (<see cref="Sorted"/>), with the same lines.
    /// </summary>
    private void CheckOrder(int offset, DatBTreeNode node, uint? lower, uint? upper)
    {
        for (var i = 1; i < node.Entries.Count; i++) Sorted(node.Entries[i - 1].Id, node.Entries[i].Id);
        if (node.Entries.Count == 0) return;
        var (first, last) = (node.Entries[0].Id, node.Entries[^1].Id);
        if (first == lower) throw ListedTwice(first);
        if (last == upper) throw ListedTwice(last);
        if (first < lower || last > upper)
            throw Damage($"B-tree node 0x{offset:X8} holds ids 0x{first:X8}-0x{last:X8}, outside the range its parent gives it ({Bound(lower)} to {Bound(upper)}): the directory is not sorted by id");
    }

    private void Sorted(uint before, uint id)
    {
        if (id == before) throw ListedTwice(id);
        if (id < before) throw Damage($"the directory lists id 0x{id:X8} after 0x{before:X8}: it is not sorted by id");
    }

    private static string Bound(uint? id) => id is { } v ? $"0x{v:X8}" : "open";

    /// <summary>
    /// Every node, depth first and in order, each reached once (structure first, as the eager walk always
    /// did); then the listing's order, which a lookup's search relies on.
    /// </summary>
    private Index Walk()
    {
        if (_root is null) return new Index([], [], new DatDirectoryShape(0, 0, BranchFill.None));
        var result = new List<DatDirectoryEntry>();
        var visited = new HashSet<int>();
        var levels = 0;
        var fill = BranchFill.None;
        Visit(_archive.Header.RootBlock, 0);
        for (var i = 1; i < result.Count; i++) Sorted(result[i - 1].Id, result[i].Id);
        var entries = result.ToArray();
        return new Index(entries, Array.ConvertAll(entries, e => e.Id), new DatDirectoryShape(visited.Count, levels, fill));

        void Visit(int offset, int depth)
        {
            if (depth > MaxDepth) throw Deeper();
            if (!visited.Add(offset)) throw ReachableTwice(offset);
            // Not kept: once walked, lookups search the walk's index.
            var node = _nodes.TryGetValue(offset, out var read) ? read : Read(offset);
            levels = Math.Max(levels, depth + 1);
            fill = fill.Combine(node.Fill);
            for (var i = 0; i < node.Entries.Count || i < node.Branches.Count; i++)
            {
                if (i < node.Branches.Count) Visit(Branch(offset, node, i), depth + 1);
                if (i < node.Entries.Count) result.Add(node.Entries[i]);
            }
        }
    }

    private DatDirectoryException Damage(string what, Exception? inner = null) => new(_archive, $"{_archive.Name}: {what}", inner);
    private DatDirectoryException ListedTwice(uint id) => Damage($"the directory lists id 0x{id:X8} twice");
    private DatDirectoryException ReachableTwice(int offset) => Damage($"B-tree node 0x{offset:X8} is reachable twice");
    private DatDirectoryException Deeper() => Damage($"B-tree deeper than {MaxDepth} levels (cycle?)");
}
