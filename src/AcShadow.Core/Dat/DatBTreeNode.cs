namespace AcShadow.Core.Dat;

/// <summary>
/// A B-tree directory node: 62 branch offsets, an entry count, then up to 61 entries, stored in a
/// block chain like any object. A node whose first branch is 0 is a leaf.
/// </summary>
public sealed record DatBTreeNode(IReadOnlyList<int> Branches, IReadOnlyList<DatDirectoryEntry> Entries)
{
    public const int MaxBranches = 62;
    public const int MaxEntries = 61;
    public const int ByteSize = MaxBranches * 4 + 4 + MaxEntries * DatDirectoryEntry.Size24;

    public bool IsLeaf => Branches.Count == 0;

    public static DatBTreeNode Read(DatBinaryReader r, int nodeOffset)
    {
        var raw = new int[MaxBranches];
        for (var i = 0; i < MaxBranches; i++) raw[i] = r.ReadInt32();
        var count = r.ReadInt32();
        if (count < 0 || count > MaxEntries)
            throw new DatFormatException($"B-tree node at 0x{nodeOffset:X8} claims {count} entries (at most {MaxEntries})");
        var entries = new DatDirectoryEntry[count];
        for (var i = 0; i < count; i++) entries[i] = DatDirectoryEntry.Read(r);
        var branches = raw[0] == 0 ? Array.Empty<int>() : raw.Take(count + 1).ToArray();
        return new DatBTreeNode(branches, entries);
    }

    public void Write(DatBinaryWriter w)
    {
        for (var i = 0; i < MaxBranches; i++) w.WriteInt32(i < Branches.Count ? Branches[i] : 0);
        w.WriteInt32(Entries.Count);
        foreach (var e in Entries) e.Write(w);
        for (var i = Entries.Count; i < MaxEntries; i++) w.WriteBytes(new byte[DatDirectoryEntry.Size24]);
    }
}
