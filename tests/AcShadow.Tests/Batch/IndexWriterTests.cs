using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Export;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;

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
        var files = Enumerable.Range(0, fileCount).Select(i => new FileEntry($"gfxobjs/0x0100000{i}.bsp.json", i == 1 ? OutputKind.Shadow : OutputKind.Bsp,
            0x01000000u + (uint)i, i, 7 * i, 1000L * i + 1, new string((char)('a' + i), 64))).ToArray();
        var skipped = new[] { new SkippedItem(0x02000001, "unreadable: \"quoted\" \\ reason", SelectionSource.Doors | SelectionSource.All) };
        var inputs = new BatchInputs(Dat, null, ShapePolicy.Retail, 1.5f, new BatchSelection(true, true, null, null)) { Formats = OutputFormats.Both };
        Assert.Equal(CanonicalJsonWriter.WriteUtf8(BatchIndexWriter.ToJson(inputs, files, skipped)), BatchIndexWriter.Write(inputs, files, skipped));
    }
}
