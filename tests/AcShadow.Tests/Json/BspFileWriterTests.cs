using AcShadow.Core.Bsp;
using AcShadow.Core.Dat;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Forge.Scale;
using AcShadow.Forging;

namespace AcShadow.Tests.Json;

/// <summary>The streaming BSP writer writes exactly what the canonical tree writer writes.</summary>
public sealed class BspFileWriterTests
{
    [Fact]
    public void The_streamed_bytes_equal_the_canonical_tree_for_every_gfxobj_of_the_sample_and_a_scale_dat()
    {
        var (sample, _) = SampleDats.Build();
        var scale = SpecCompiler.Compile(ScaleSpecGenerator.Generate(80, 5)).Portal;
        var compared = 0;
        foreach (var bytes in new[] { sample, scale })
        {
            using var dat = DatDatabase.Open(new MemoryStream(bytes), "dat");
            foreach (var id in dat.ListIds(DatObjectKind.GfxObj))
            {
                if (BspExtractor.Extract(dat.ReadGfxObj(id)!) is not { } dump) continue;
                var expected = CanonicalJsonWriter.WriteUtf8(BspFileWriter.ToJson(dump));
                Assert.True(expected.AsSpan().SequenceEqual(BspFileWriter.Write(dump)), $"0x{id:X8} differs");
                compared++;
            }
        }
        Assert.True(compared > 100, $"{compared} dumps compared");
    }

    [Fact]
    public void Odd_values_are_written_as_the_tree_writes_them()
    {
        var (sample, _) = SampleDats.Build();
        using var dat = DatDatabase.Open(new MemoryStream(sample), "dat");
        var dump = BspExtractor.Extract(dat.ReadGfxObj(0x01006000)!)!; // degenerate and non-planar polygons
        var odd = dump with
        {
            BoundingSphere = dump.BoundingSphere with { Radius = float.NaN, Center = new(-0f, float.PositiveInfinity, 1e-30f) },
            Diagnostics = ["quote \" backslash \\ newline \n tab \t control \u0001 é"],
        };
        Assert.Equal(CanonicalJsonWriter.WriteUtf8(BspFileWriter.ToJson(odd)), BspFileWriter.Write(odd));
    }
}
