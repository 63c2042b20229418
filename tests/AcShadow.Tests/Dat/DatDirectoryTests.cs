using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Dat;

/// <summary>
/// Issue 30 item 5: the directory is read as lookups need it. A lookup reads only the nodes on its path
/// (counted by the directory itself), lookups and the whole walk agree, and a node out of order is refused
/// by both with the same line.
/// </summary>
public class DatDirectoryTests
{
    private const int BlockSize = 256;
    private const uint Door = 0x020019FF;

    /// <summary>More entries than two levels hold (61 + 62 x 61): a three-level directory; every third id.</summary>
    private static readonly Dictionary<uint, byte[]> ThreeLevels =
        Enumerable.Range(0, 4000).ToDictionary(i => 0x01000000u + 3u * (uint)i, i => new byte[] { (byte)i, 1, 2, 3 });

    private static byte[] Forged(IReadOnlyDictionary<uint, byte[]> objects) =>
        DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, BlockSize));

    private static DatArchive Open(byte[] dat) => DatArchive.Open(new MemoryStream(dat, writable: false), "client_portal.dat");

    [Fact]
    public void Opening_reads_the_root_and_a_lookup_only_the_nodes_on_its_path()
    {
        var dat = Forged(ThreeLevels);
        using var walked = Open(dat);
        var shape = walked.DirectoryShape;
        Assert.Equal(3, shape.Levels);

        using var archive = Open(dat);
        Assert.Equal(1, archive.Directory.NodeReads);

        // An id in a leaf: the root, one internal node, the leaf.
        Assert.True(archive.TryGetEntry(0x01000000u + 3u * 1234, out _));
        Assert.Equal(3, archive.Directory.NodeReads);
        // Its neighbour shares the path: nothing more is read.
        Assert.True(archive.TryGetEntry(0x01000000u + 3u * 1235, out _));
        Assert.Equal(3, archive.Directory.NodeReads);
        // An id that is not there costs its path too, no more.
        Assert.False(archive.TryGetEntry(0x01000000u + 3u * 3000 + 1, out _));
        Assert.InRange(archive.Directory.NodeReads, 4, 5);

        // Listing walks the rest, reading each node once (those already read are not read again).
        Assert.Equal(ThreeLevels.Count, archive.Entries.Count);
        Assert.Equal(shape.Nodes, archive.Directory.NodeReads);
    }

    [Fact]
    public void Exporting_the_door_reads_a_few_directory_nodes_of_a_scale_dat()
    {
        // The scale forge's dat (the benchmark's, smaller): 1,000 Setups and their GfxObjs, a three-level directory.
        var portal = SpecCompiler.Compile(ScaleSpecGenerator.Generate(1000, 1)).Portal;
        using var listed = DatDatabase.Open(new MemoryStream(portal, writable: false), "client_portal.dat");
        var shape = listed.Archive.DirectoryShape;
        Assert.Equal(3, shape.Levels);

        using var dat = DatDatabase.Open(new MemoryStream(portal, writable: false), "client_portal.dat");
        var export = new ExportEngine(dat, new ShapeBuildOptions(ShapePolicy.Retail, 1f)).ExportSetup(Door);

        // What `dump --setup 0x020019FF` reads: the Setup, its parts, motion table and animation, each by a
        // lookup of at most three nodes, many shared (the root always).
        Assert.NotNull(export);
        Assert.InRange(dat.Archive.Directory.NodeReads, 3, 3 * 8);
        Assert.True(dat.Archive.Directory.NodeReads * 10 < shape.Nodes, $"{dat.Archive.Directory.NodeReads} of {shape.Nodes} nodes read");
    }

    public static TheoryData<string> Dats() => ["sample", "three levels"];

    [Theory]
    [MemberData(nameof(Dats))]
    public void Lookups_find_every_entry_the_walk_lists_and_nothing_else(string which)
    {
        var dat = which == "sample" ? SampleDat.PortalBytes : Forged(ThreeLevels);
        using var walked = Open(dat);
        using var searched = Open(dat);
        var all = walked.Entries;
        Assert.True(all.Count > 0);
        foreach (var entry in all)
        {
            Assert.True(searched.TryGetEntry(entry.Id, out var found), $"0x{entry.Id:X8} not found by search");
            Assert.Equal(entry, found);
        }
        var listed = all.Select(e => e.Id).ToHashSet();
        foreach (var missing in new[] { 0u, uint.MaxValue }.Concat(all.Select(e => e.Id + 1)).Concat(all.Select(e => e.Id - 1)).Where(id => !listed.Contains(id)))
            Assert.False(searched.TryGetEntry(missing, out _), $"0x{missing:X8} found but never written");
        // Searched after the walk (the flat index), the same answers.
        foreach (var entry in all) Assert.True(walked.TryGetEntry(entry.Id, out var again) && again == entry);
    }

    /// <summary>Where entry <paramref name="i"/>'s id of the root node sits (the root is a leaf here: one block chain, contiguous).</summary>
    private static int RootEntryId(byte[] dat, int i)
    {
        var root = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(0x160));
        // Payload offset of the id: 62 branches, the count, then 24-byte entries whose id follows 4 bytes of flags and version.
        var payload = DatBTreeNode.MaxBranches * 4 + 4 + i * DatDirectoryEntry.Size24 + 4;
        var block = payload / (BlockSize - 4);
        return root + block * BlockSize + 4 + payload % (BlockSize - 4);
    }

    [Theory]
    [InlineData(false, "the directory lists id 0x01000012 after 0x01000015: it is not sorted by id")]
    [InlineData(true, "the directory lists id 0x01000012 twice")]
    public void A_node_out_of_order_is_refused_by_the_walk_and_by_a_lookup_with_the_same_line(bool duplicate, string reason)
    {
        // 20 ids, every third: the root is the only node. Entries 6 and 7 (0x01000012, 0x01000015) swapped, or 7 made 6's id.
        var dat = Forged(ThreeLevels.Take(20).ToDictionary());
        var (six, seven) = (RootEntryId(dat, 6), RootEntryId(dat, 7));
        Assert.Equal(0x01000015u, BinaryPrimitives.ReadUInt32LittleEndian(dat.AsSpan(seven)));
        if (!duplicate) BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(six), 0x01000015u);
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(seven), 0x01000012u);

        using var walked = Open(dat);
        using var searched = Open(dat);
        var walk = Assert.Throws<DatDirectoryException>(() => walked.Entries);
        var lookup = Assert.Throws<DatDirectoryException>(() => searched.TryGetEntry(0x01000000u, out _));

        Assert.Equal("client_portal.dat: " + reason, walk.Message);
        Assert.Equal(walk.Message, lookup.Message);
    }
}
