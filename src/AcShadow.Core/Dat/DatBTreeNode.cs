using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat;

/// <summary>
/// A B-tree directory node: 62 branch offsets, an entry count, then up to 61 entries, stored in a
/// block chain like any object. A node whose first branch is "no branch" (0 in retail dats, 0xCDCDCDCD in
/// dats DatReaderWriter wrote) is a leaf; an internal node's first count + 1 branches are its children.
/// </summary>
public sealed record DatBTreeNode(IReadOnlyList<int> Branches, IReadOnlyList<DatDirectoryEntry> Entries)
{
    public const int MaxBranches = 62;
    public const int MaxEntries = 61;
    public const int ByteSize = MaxBranches * 4 + 4 + MaxEntries * DatDirectoryEntry.Size24;

    public bool IsLeaf => Branches.Count == 0;

    /// <summary>What the unused branch slots held when the node was read; what <see cref="Write"/> puts there.</summary>
    public BranchFill Fill { get; init; } = BranchFill.Zero;

    public static DatBTreeNode Read(DatBinaryReader r, int nodeOffset)
    {
        var raw = new int[MaxBranches];
        for (var i = 0; i < MaxBranches; i++) raw[i] = r.ReadInt32();
        var count = r.ReadInt32();
        if (count < 0 || count > MaxEntries)
            throw new DatFormatException($"B-tree node at 0x{nodeOffset:X8} claims {count} entries (at most {MaxEntries})");
        var entries = new DatDirectoryEntry[count];
        for (var i = 0; i < count; i++) entries[i] = DatDirectoryEntry.Read(r);
        // A "no branch" among an internal node's first count + 1 is damage, refused when it is followed.
        var used = BranchFills.IsNoBranch(raw[0]) ? 0 : count + 1;
        var leaf = used == 0;
        return new DatBTreeNode(leaf ? [] : raw[..used], entries) { Fill = FillOf(raw.AsSpan(used)) };
    }

    private static BranchFill FillOf(ReadOnlySpan<int> unused)
    {
        if (unused.IsEmpty) return BranchFill.None;
        if (!unused.ContainsAnyExcept(0)) return BranchFill.Zero;
        if (!unused.ContainsAnyExcept(BranchFills.Cdcd)) return BranchFill.Cdcd;
        return BranchFill.Other;
    }

    /// <summary>Writes the node with its unused branch slots set as <see cref="Fill"/> says (0 unless Cdcd).</summary>
    public void Write(DatBinaryWriter w)
    {
        var unused = Fill == BranchFill.Cdcd ? BranchFills.Cdcd : 0;
        for (var i = 0; i < MaxBranches; i++) w.WriteInt32(i < Branches.Count ? Branches[i] : unused);
        w.WriteInt32(Entries.Count);
        foreach (var e in Entries) e.Write(w);
        for (var i = Entries.Count; i < MaxEntries; i++) w.WriteBytes(new byte[DatDirectoryEntry.Size24]);
    }
}
