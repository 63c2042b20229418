using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Tests.Batch;

/// <summary>index.json's streamed files array writes exactly what the canonical tree writes.</summary>
public sealed class IndexWriterTests
{
    private static readonly DatSourceInfo Dat = new("client_portal.dat", 1024, DatFileKind.Portal, 1, 1024);

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(3)]
    public void The_streamed_index_equals_the_canonical_tree(int fileCount)
    {
        var files = Enumerable.Range(0, fileCount).Select(i => new FileEntry($"gfxobjs/0x0100000{i}.bsp.json", i == 1 ? FixtureKind.Shadow : FixtureKind.Bsp,
            0x01000000u + (uint)i, i, 7 * i, 1000L * i + 1, new string((char)('a' + i), 64))).ToArray();
        var skipped = new[] { new SkippedItem(0x02000001, "unreadable: \"quoted\" \\ reason", SelectionSource.Doors | SelectionSource.All) };
        var inputs = new BatchInputs(Dat, null, ShapePolicy.Retail, 1.5f, new BatchSelection(true, true, null, null)) { Formats = OutputFormats.Both };
        Assert.Equal(CanonicalJsonWriter.WriteUtf8(BatchIndexWriter.ToJson(inputs, files, skipped)), BatchIndexWriter.Write(inputs, files, skipped));
    }

    [Fact]
    public void An_index_streamed_in_many_chunks_equals_the_canonical_tree_and_the_in_memory_bytes()
    {
        // 3,000 entries is about 750 KB: a dozen chunks, with entries split across chunk boundaries.
        var files = Enumerable.Range(0, 3000).Select(i => new FileEntry($"gfxobjs/0x{0x01000000 + i:X8}.bsp.json", FixtureKind.Bsp,
            0x01000000u + (uint)i, 0, i % 2000, 100L * i, Convert.ToHexStringLower(BitConverter.GetBytes(i * 2654435761L)).PadLeft(64, '0'))).ToArray();
        var inputs = new BatchInputs(Dat, null, ShapePolicy.Retail, 1f, new BatchSelection(false, true, null, null));
        var streamed = new MemoryStream();
        BatchIndexWriter.Write(streamed, inputs, files, []);
        var tree = CanonicalJsonWriter.WriteUtf8(BatchIndexWriter.ToJson(inputs, files, []));
        Assert.True(tree.Length > 10 * 64 * 1024, $"{tree.Length} bytes");
        Assert.Equal(tree, streamed.ToArray());
        Assert.Equal(tree, BatchIndexWriter.Write(inputs, files, []));
    }
}
