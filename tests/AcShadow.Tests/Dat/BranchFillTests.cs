using AcShadow.Forge;
using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Dat;

/// <summary>
/// Directories whose unused branch slots hold 0xCDCDCDCD, as DatReaderWriter writes them, open as retail's
/// zero-filled ones do; a branch pointer that is really damaged is still refused.
/// </summary>
public class BranchFillTests
{
    private const int Cdcd = unchecked((int)0xCDCDCDCD);

    private static Dictionary<uint, byte[]> Objects(int count)
    {
        var objects = new Dictionary<uint, byte[]>();
        for (var i = 0; i < count; i++) objects[0x01000000u + (uint)(i * 7)] = [(byte)i, (byte)(i >> 8), 0x5A];
        return objects;
    }

    private static byte[] Dat(int count, BranchFill fill) =>
        DatArchiveWriter.Write(Objects(count), new DatArchiveWriter.Options(DatFileKind.Portal, 256, Fill: fill));

    private static DatArchive Open(byte[] dat) => DatArchive.Open(new MemoryStream(dat, writable: false), "drw.dat");

    private static int Root(byte[] dat) => BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(0x160));

    /// <summary>
    /// Where branch slot i of the node at <paramref name="node"/> lies: after the block's next-block offset. With
    /// 256-byte blocks the 62 slots and the entry count (bytes 0-251 of the node) all fit the first block.
    /// </summary>
    private static int SlotAt(int node, int i) => node + 4 + i * 4;

    private static int EntryCount(byte[] dat, int node) => BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(SlotAt(node, DatBTreeNode.MaxBranches)));

    [Theory]
    [InlineData(1, 1)]
    [InlineData(61, 1)]
    [InlineData(500, 2)]
    [InlineData(4000, 3)] // a two-level tree holds at most 3843 entries
    public void A_DatReaderWriter_filled_directory_reads_as_the_retail_one_at_every_level(int count, int levels)
    {
        var zero = Dat(count, BranchFill.Zero);
        var cdcd = Dat(count, BranchFill.Cdcd);
        Assert.NotEqual(zero, cdcd);

        // Lookups first (they search the tree from the root), then the full walk.
        using (var searched = Open(cdcd))
            foreach (var (id, content) in Objects(count)) Assert.Equal(content, searched.ReadObjectBytes(id));
        using var a = Open(zero);
        using var b = Open(cdcd);
        Assert.Equal(a.Entries, b.Entries);
        Assert.Equal(count, b.Entries.Count);
        Assert.Equal(new DatDirectoryShape(a.DirectoryShape.Nodes, levels, BranchFill.Cdcd), b.DirectoryShape);
        Assert.Equal(new DatDirectoryShape(a.DirectoryShape.Nodes, levels, BranchFill.Zero), a.DirectoryShape);
    }

    [Fact]
    public void The_fill_is_written_where_DatReaderWriter_writes_it()
    {
        // A leaf: every one of the 62 slots is fill, the first marking it a leaf.
        var leaf = Dat(3, BranchFill.Cdcd);
        var root = Root(leaf);
        for (var i = 0; i < DatBTreeNode.MaxBranches; i++)
            Assert.Equal(Cdcd, BinaryPrimitives.ReadInt32LittleEndian(leaf.AsSpan(SlotAt(root, i))));

        // An internal node: count + 1 real branches, then fill.
        var tree = Dat(500, BranchFill.Cdcd);
        root = Root(tree);
        var count = EntryCount(tree, root);
        var slots = Enumerable.Range(0, DatBTreeNode.MaxBranches).Select(i => BinaryPrimitives.ReadInt32LittleEndian(tree.AsSpan(SlotAt(root, i)))).ToArray();
        Assert.InRange(count, 1, DatBTreeNode.MaxEntries - 1);
        Assert.DoesNotContain(slots[..(count + 1)], s => s is 0 or Cdcd);
        Assert.All(slots[(count + 1)..], s => Assert.Equal(Cdcd, s));
    }

    [Fact]
    public void A_retail_directory_patched_by_a_DatReaderWriter_tool_is_mixed()
    {
        var dat = Dat(500, BranchFill.Zero);
        var root = Root(dat);
        for (var i = EntryCount(dat, root) + 1; i < DatBTreeNode.MaxBranches; i++)
            BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(SlotAt(root, i)), Cdcd);

        using var archive = Open(dat);

        Assert.Equal(500, archive.Entries.Count);
        Assert.Equal(BranchFill.Mixed, archive.DirectoryShape.Fill);
    }

    [Theory]
    [InlineData(BranchFill.Zero, 0x12345678)]  // past the end of the file
    [InlineData(BranchFill.Cdcd, 0x12345678)]
    [InlineData(BranchFill.Cdcd, 0)]           // "no branch" where the node needs one
    [InlineData(BranchFill.Cdcd, Cdcd)]
    [InlineData(BranchFill.Zero, Cdcd)]
    public void A_damaged_branch_pointer_is_still_refused(BranchFill fill, int damaged)
    {
        var dat = Dat(500, fill);
        var root = Root(dat);
        BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(SlotAt(root, 1)), damaged);

        // Refused by the walk, and by a lookup under branch 1 (a "no branch" where one is needed, or a pointer
        // outside the file), with the same line.
        var walk = Assert.Throws<DatDirectoryException>(() =>
        {
            using var walked = Open(dat);
            return walked.Entries;
        });
        var lookup = Assert.Throws<DatDirectoryException>(() =>
        {
            using var searched = Open(dat);
            return Objects(500).Keys.Order().Select(searched.ReadObjectBytes).ToArray();
        });
        Assert.Equal(walk.Message, lookup.Message);
    }
}

/// <summary>The whole batch output is the same whichever tool's fill the directory carries.</summary>
public class BranchFillOutputTests
{
    [Fact]
    public void A_DatReaderWriter_style_sample_gives_byte_identical_batch_output()
    {
        var spec = SampleSpecAuthor.Create();
        string[] Run(BranchFill fill, TempDir dats, TempDir output)
        {
            var forged = SpecCompiler.Compile(spec, fill);
            File.WriteAllBytes(Path.Combine(dats.Path, "client_portal.dat"), forged.Portal);
            File.WriteAllBytes(Path.Combine(dats.Path, "client_cell_1.dat"), forged.Cell!);
            var run = CliRun.Of("batch", "--doors", "--all", "--landblock", "0xA9B4", "--dat", dats.Path,
                "--cell-dat", Path.Combine(dats.Path, "client_cell_1.dat"), "--out", output.Path, "--quiet");
            Assert.True(run.ExitCode == 0, run.Error);
            return [.. output.Files()];
        }

        using var retailDats = new TempDir();
        using var drwDats = new TempDir();
        using var retail = new TempDir();
        using var drw = new TempDir();
        var files = Run(BranchFill.Zero, retailDats, retail);
        Assert.Equal(files, Run(BranchFill.Cdcd, drwDats, drw));
        Assert.NotEqual(File.ReadAllBytes(Path.Combine(retailDats.Path, "client_portal.dat")), File.ReadAllBytes(Path.Combine(drwDats.Path, "client_portal.dat")));
        Assert.True(files.Length > 20);
        foreach (var file in files.Where(f => f != "index.json"))
            Assert.Equal(File.ReadAllBytes(Path.Combine(retail.Path, file)), File.ReadAllBytes(Path.Combine(drw.Path, file)));
        // index.json records each dat's SHA-256, and these are two dats: that, and only that, differs.
        string Index(TempDir output, TempDir dats) => DatHashes(dats).Aggregate(File.ReadAllText(Path.Combine(output.Path, "index.json")),
            (text, hash) => text.Replace(hash, "(the dat's SHA-256)", StringComparison.Ordinal));
        Assert.NotEqual(DatHashes(retailDats), DatHashes(drwDats));
        Assert.Equal(Index(retail, retailDats), Index(drw, drwDats));
        Assert.Contains("(the dat's SHA-256)", Index(retail, retailDats));
    }

    private static string[] DatHashes(TempDir dats) =>
        [.. new[] { "client_portal.dat", "client_cell_1.dat" }.Select(name => Convert.ToHexStringLower(System.Security.Cryptography.SHA256.HashData(File.ReadAllBytes(Path.Combine(dats.Path, name)))))];
}
