using System.Buffers.Binary;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;

namespace AcShadow.Tests.Dat;

public class DatArchiveTests
{
    private static Dictionary<uint, byte[]> Objects(int count, int seed, int maxSize)
    {
        var random = new Random(seed);
        var objects = new Dictionary<uint, byte[]>();
        while (objects.Count < count)
        {
            var id = 0x01000000u + (uint)random.Next(0, 0xFFFF);
            var bytes = new byte[random.Next(0, maxSize)];
            random.NextBytes(bytes);
            objects[id] = bytes;
        }
        return objects;
    }

    [Theory]
    [InlineData(0, 1024)]
    [InlineData(1, 1024)]
    [InlineData(61, 1024)]
    [InlineData(62, 256)]
    [InlineData(500, 1024)]
    [InlineData(4000, 256)] // needs a three-level B-tree (a two-level one holds 3843)
    public void Every_object_written_reads_back_byte_for_byte(int count, int blockSize)
    {
        var objects = Objects(count, count, 3000);
        var bytes = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, blockSize));
        using var archive = DatArchive.Open(new MemoryStream(bytes), "test.dat");
        Assert.Equal(blockSize, archive.Header.BlockSize);
        Assert.Equal(bytes.Length, archive.Header.FileSize);
        Assert.Equal(objects.Keys.OrderBy(k => k), archive.Entries.Select(e => e.Id));
        foreach (var (id, content) in objects) Assert.Equal(content, archive.ReadObjectBytes(id));
        Assert.Null(archive.ReadObjectBytes(0x02000000));
    }

    [Fact]
    public void Writing_is_deterministic()
    {
        var objects = Objects(300, 3, 2000);
        var a = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal));
        var b = DatArchiveWriter.Write(new Dictionary<uint, byte[]>(objects.Reverse()), new DatArchiveWriter.Options(DatFileKind.Portal));
        Assert.Equal(a, b);
    }

    [Fact]
    public void Header_carries_the_retail_magic_at_0x140()
    {
        var bytes = DatArchiveWriter.Write(Objects(3, 1, 10), new DatArchiveWriter.Options(DatFileKind.Cell, 256));
        Assert.Equal(0x5442, BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(0x140)));
        using var archive = DatArchive.Open(new MemoryStream(bytes), "cell.dat");
        Assert.Equal(DatFileKind.Cell, archive.Header.Kind);
    }

    [Fact]
    public void A_file_that_is_not_a_dat_is_refused_with_a_reason()
    {
        var e = Assert.Throws<DatFormatException>(() => DatArchive.Open(new MemoryStream(new byte[4096]), "zeros.dat"));
        Assert.Contains("magic", e.Message);
        var shortFile = Assert.Throws<DatFormatException>(() => DatArchive.Open(new MemoryStream(new byte[10]), "short.dat"));
        Assert.Contains("too short", shortFile.Message);
    }

    [Fact]
    public void A_truncated_dat_is_refused_not_misread()
    {
        var bytes = DatArchiveWriter.Write(Objects(200, 5, 4000), new DatArchiveWriter.Options(DatFileKind.Portal));
        var truncated = bytes.AsSpan(0, bytes.Length / 2).ToArray();
        // The directory (read at open, or as the walk reaches it) or an object, whichever the cut reaches first.
        var refused = Record.Exception(() =>
        {
            using var archive = DatArchive.Open(new MemoryStream(truncated), "truncated.dat");
            foreach (var e in archive.Entries) archive.ReadObjectBytes(e.Id);
        });
        Assert.True(refused is DatFormatException or DatDirectoryException, refused?.ToString() ?? "not refused");
    }

    [Theory]
    [InlineData(0u)]
    [InlineData(0x7Fu)]
    [InlineData(0x80u)]
    [InlineData(0x3FFFu)]
    [InlineData(0x4000u)]
    [InlineData(0x3FFFFFFFu)]
    public void Compressed_uints_round_trip(uint value)
    {
        var w = new DatBinaryWriter();
        w.WriteCompressedUInt32(value);
        var bytes = w.ToArray();
        Assert.Equal(value < 0x80 ? 1 : value < 0x4000 ? 2 : 4, bytes.Length);
        Assert.Equal(value, new DatBinaryReader(bytes, "test").ReadCompressedUInt32());
    }

    [Fact]
    public void A_dat_on_disk_reads_the_same_bytes_from_many_threads_at_once()
    {
        // A file is read through positional reads without the lock; the same dat from memory through the lock.
        // Objects up to 300 KB span runs of blocks longer than one positional read holds.
        var objects = Objects(300, 7, 300_000);
        var bytes = DatArchiveWriter.Write(objects, new DatArchiveWriter.Options(DatFileKind.Portal, 1024));
        using var dir = new AcShadow.Tests.Support.TempDir();
        var path = Path.Combine(dir.Path, "client_portal.dat");
        File.WriteAllBytes(path, bytes);
        using var fromFile = DatArchive.Open(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.RandomAccess), "client_portal.dat");
        var ids = objects.Keys.ToArray();
        var read = new byte[ids.Length][];
        Parallel.For(0, ids.Length * 4, new ParallelOptions { MaxDegreeOfParallelism = 8 }, i =>
        {
            var content = fromFile.ReadObjectBytes(ids[i % ids.Length]);
            if (i < ids.Length) read[i] = content!;
            else Assert.Equal(objects[ids[i % ids.Length]], content);
        });
        for (var i = 0; i < ids.Length; i++) Assert.Equal(objects[ids[i]], read[i]);
        Assert.Contains(objects.Values, o => o.Length > 256 * 1024);
    }
}
