using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fuzz;

/// <summary>
/// The dat layer's answer to what the fuzz campaign found: any damaged object is one
/// <see cref="DatFormatException"/> reading "corrupt dat" with the object's id, a damaged size cannot make
/// it allocate more than the file, and cyclic block chains and B-trees end.
/// </summary>
public class CorruptDatTests
{
    private const uint Door = 0x020019FF;
    private const int BlockSize = 1024;

    /// <summary>A dat holding only the sample door's Setup, and where its directory entry's fields sit.</summary>
    private static (byte[] Dat, int EntryAt) OneSetupDat()
    {
        using var sample = SampleDat.OpenPortal();
        var bytes = sample.Archive.ReadObjectBytes(Door)!;
        var dat = DatArchiveWriter.Write(new Dictionary<uint, byte[]> { [Door] = bytes }, new DatArchiveWriter.Options(DatFileKind.Portal, BlockSize));
        var root = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(0x160));
        // Node payload: 62 branches, the entry count, then entry 0 (flags+version, id, offset, size, …).
        return (dat, root + 4 + DatBTreeNode.MaxBranches * 4 + 4);
    }

    private static DatDatabase Open(byte[] dat) => DatDatabase.Open(new MemoryStream(dat, writable: false), "client_portal.dat");

    [Theory]
    [InlineData(0xFFFFFFFFu)] // found by the campaign: an OverflowException, exit 1 ("internal error")
    [InlineData(0x80000000u)]
    [InlineData(0x40000000u)] // found by the campaign: allocated 1 GiB before reading the chain
    [InlineData(0x7FFFFFFFu)]
    public void A_directory_size_larger_than_the_file_is_a_corrupt_object_without_allocating_it(uint size)
    {
        var (dat, entryAt) = OneSetupDat();
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(entryAt + 12), size);
        using var db = Open(dat);

        var before = GC.GetAllocatedBytesForCurrentThread();
        var e = Assert.Throws<DatFormatException>(() => db.ReadSetup(Door));
        var allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.StartsWith("corrupt dat: Setup 0x020019FF in client_portal.dat: ", e.Message);
        Assert.Equal(Door, e.ObjectId);
        Assert.True(allocated < 1 << 20, $"allocated {allocated} bytes");
    }

    [Fact]
    public void A_size_that_outgrows_a_valid_chain_allocates_only_what_the_chain_holds()
    {
        var (dat, entryAt) = OneSetupDat();
        // As many bytes as the whole file could hold: the chain ends (next pointer 0) long before.
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(entryAt + 12), (uint)(dat.Length / BlockSize * (BlockSize - 4)));
        using var db = Open(dat);
        var e = Assert.Throws<DatFormatException>(() => db.ReadSetup(Door));
        Assert.Contains("outside the", e.Message);
    }

    [Fact]
    public void A_block_chain_that_loops_ends_with_a_corrupt_object()
    {
        var (dat, entryAt) = OneSetupDat();
        var first = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(entryAt + 8));
        BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(first), first); // the first block's next pointer: itself
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(entryAt + 12), (uint)(dat.Length / BlockSize * (BlockSize - 4)));
        using var db = Open(dat);
        var e = Assert.Throws<DatFormatException>(() => db.ReadSetup(Door));
        Assert.Contains("loops", e.Message);
        Assert.Equal(Door, e.ObjectId);
    }

    [Fact]
    public void A_b_tree_whose_branch_points_back_at_its_root_is_refused_by_the_walk_and_by_any_lookup()
    {
        var (dat, _) = OneSetupDat();
        var root = BinaryPrimitives.ReadInt32LittleEndian(dat.AsSpan(0x160));
        BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(root + 4), root); // branch 0 → the root itself
        var expected = "client_portal.dat: B-tree node 0x" + root.ToString("X8") + " is reachable twice";
        using var db = Open(dat);
        // A listing walks the whole directory; a lookup checks every branch of each node it reads, so even the
        // door, which sits in the root, meets the branch back onto the root.
        Assert.Equal(expected, Assert.Throws<DatDirectoryException>(() => db.Archive.Entries).Message);
        Assert.Equal(expected, Assert.Throws<DatDirectoryException>(() => db.ReadSetup(Door)).Message);
        Assert.Equal(expected, Assert.Throws<DatDirectoryException>(() => db.ReadSetup(0x02000001)).Message);
    }

    [Fact]
    public void A_lookup_finds_every_entry_the_full_walk_lists_and_nothing_else()
    {
        // More entries than two levels hold (61 + 62 x 61), so searches descend through three; every third id.
        var objects = Enumerable.Range(0, 4000).ToDictionary(i => 0x01000000u + 3u * (uint)i, i => new byte[] { (byte)i, 1, 2, 3 });
        var bytes = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, BlockSize: 256));
        using var searched = DatArchive.Open(new MemoryStream(bytes), "client_portal.dat");
        using var walked = DatArchive.Open(new MemoryStream(bytes), "client_portal.dat");
        var all = walked.Entries;
        Assert.Equal(objects.Count, all.Count);
        foreach (var entry in all)
        {
            Assert.True(searched.TryGetEntry(entry.Id, out var found), $"0x{entry.Id:X8} not found by search");
            Assert.Equal(entry, found);
        }
        foreach (var missing in new[] { 0u, 0x00FFFFFFu }.Concat(all.Select(e => e.Id + 1)).Concat(all.Select(e => e.Id + 2)))
            Assert.False(searched.TryGetEntry(missing, out _), $"0x{missing:X8} found but never written");
    }

    [Fact]
    public void A_truncated_object_names_its_kind_and_id_once()
    {
        var (dat, entryAt) = OneSetupDat();
        var size = BinaryPrimitives.ReadUInt32LittleEndian(dat.AsSpan(entryAt + 12));
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(entryAt + 12), size / 2);
        using var db = Open(dat);
        var e = Assert.Throws<DatFormatException>(() => db.ReadSetup(Door));
        Assert.StartsWith("corrupt dat: Setup 0x020019FF in client_portal.dat: needs ", e.Message);
        Assert.Single(System.Text.RegularExpressions.Regex.Matches(e.Message, "0x020019FF"));
        // Asked again (the cache keeps the failure), the same answer.
        Assert.Equal(e.Message, Assert.Throws<DatFormatException>(() => db.ReadSetup(Door)).Message);
    }

    [Fact]
    public void The_archive_names_the_object_whose_chain_is_damaged()
    {
        var (dat, entryAt) = OneSetupDat();
        BinaryPrimitives.WriteInt32LittleEndian(dat.AsSpan(entryAt + 8), dat.Length + BlockSize); // chain start past the end
        using var archive = DatArchive.Open(new MemoryStream(dat), "client_portal.dat");
        var e = Assert.Throws<DatFormatException>(() => archive.ReadObjectBytes(Door));
        Assert.StartsWith("corrupt dat: object 0x020019FF in client_portal.dat: its block chain points at", e.Message);
    }

    [Fact]
    public void Any_exception_met_reading_an_object_leaves_the_dat_source_as_a_corrupt_dat_naming_the_object()
    {
        var (dat, _) = OneSetupDat();
        var stream = new StreamThatFailsOnDemand(dat);
        using var db = DatDatabase.Open(stream, "client_portal.dat");
        stream.Failure = new IndexOutOfRangeException("simulated");

        var e = Assert.Throws<DatFormatException>(() => db.ReadSetup(Door));

        Assert.Equal("corrupt dat: Setup 0x020019FF in client_portal.dat: IndexOutOfRangeException: simulated", e.Message);
        Assert.Equal(Door, e.ObjectId);
        Assert.IsType<IndexOutOfRangeException>(e.InnerException);
    }

    private sealed class StreamThatFailsOnDemand(byte[] bytes) : MemoryStream(bytes, writable: false)
    {
        public Exception? Failure { get; set; }

        public override int Read(Span<byte> buffer) => Failure is { } f ? throw f : base.Read(buffer);

        public override int Read(byte[] buffer, int offset, int count) => Failure is { } f ? throw f : base.Read(buffer, offset, count);
    }

    [Fact]
    public void Dump_on_a_damaged_setup_exits_3_saying_corrupt_dat_and_the_id()
    {
        var (dat, entryAt) = OneSetupDat();
        var size = BinaryPrimitives.ReadUInt32LittleEndian(dat.AsSpan(entryAt + 12));
        BinaryPrimitives.WriteUInt32LittleEndian(dat.AsSpan(entryAt + 12), size / 2);
        using var dir = new TempDir();
        var path = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(path, dat);

        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--dat", path, "--out", Path.Combine(dir.Path, "out"));

        Assert.Equal(3, run.ExitCode);
        var line = Assert.Single(run.ErrorLines);
        Assert.Contains("corrupt dat: Setup 0x020019FF", line);
        Assert.False(Directory.Exists(Path.Combine(dir.Path, "out")));
    }
}
