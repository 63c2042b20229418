using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Dat;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Tests.Support;
using static AcShadow.Tests.Errors.BrokenDats;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md, "inside a valid dat": faults in one object are diagnostics in its files and
/// `warning:` lines on stderr, never a crash, and a batch goes on with the other Setups.
/// </summary>
public class CorruptContentTests
{
    private const uint Broken = 0x02000002;
    private const uint BrokenGfx = 0x01000002;

    private static (CliRun Dump, CliRun Batch, TempDir Out) DumpAndBatch(byte[] portal)
    {
        using var dat = Folder(portal);
        var output = new TempDir();
        var dump = CliRun.Of("dump", "--setup", "0x02000002", "--dat", dat.Path, "--out", Path.Combine(output.Path, "dump"));
        var batch = CliRun.Of("batch", "--all", "--dat", dat.Path, "--out", Path.Combine(output.Path, "batch"), "--quiet");
        return (dump, batch, output);
    }

    private static string Text(TempDir dir, string relative) => File.ReadAllText(Path.Combine(dir.Path, relative));

    /// <summary>The healthy Setup beside the broken one was exported, and the index lists both.</summary>
    private static void BatchWentOn(CliRun batch, TempDir output)
    {
        Assert.Equal(0, batch.ExitCode);
        Assert.True(File.Exists(Path.Combine(output.Path, "batch/setups/0x02000001.shadow.json")), batch.Out + batch.Error);
        Assert.True(File.Exists(Path.Combine(output.Path, "batch/index.json")));
        Assert.DoesNotContain("   at ", batch.Error);
    }

    [Fact]
    public void A_part_whose_GfxObj_is_missing_is_a_diagnostic_and_the_batch_goes_on()
    {
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, 0x0100FFFF, HealthyGfxObj))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("warning: 0x02000002: missing-gfxobj: part 0 (GfxObj 0x0100FFFF) is not in the dat", dump.Error);
            Assert.Contains("\"missing-gfxobj\"", Text(output, "dump/setups/0x02000002.shadow.json"));
            BatchWentOn(batch, output);
            Assert.Contains("\"missing-gfxobj\"", Text(output, "batch/setups/0x02000002.shadow.json"));
        }
    }

    [Fact]
    public void A_polygon_naming_a_vertex_that_does_not_exist_is_a_diagnostic_and_the_polygon_gets_no_plane()
    {
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx)), Bytes(Box(BrokenGfx, polygonVertices: [0, 1, 2, 77]))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("GfxObj 0x01000002 polygon 0: vertex id(s) 77 not in the vertex array", dump.Error);
            var bsp = BspFileReader.Read(Text(output, "dump/gfxobjs/0x01000002.bsp.json"));
            Assert.Null(Assert.Single(bsp.Polygons).Plane);
            Assert.Contains(CompiledBsp.Compile(bsp).Diagnostics, d => d.Code == CollisionDiagnosticCodes.SkippedPolygon);
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void A_BSP_leaf_naming_a_polygon_that_does_not_exist_is_a_diagnostic()
    {
        var leaf = new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 1f), 0, 1, [0, 9]);
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx)), Bytes(Box(BrokenGfx, bsp: leaf))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("GfxObj 0x01000002 BSP leaf 0: polygon id 9 is not a physics polygon", dump.Error);
            var bsp = BspFileReader.Read(Text(output, "dump/gfxobjs/0x01000002.bsp.json"));
            Assert.Contains(CompiledBsp.Compile(bsp).Diagnostics, d => d.Code == CollisionDiagnosticCodes.MissingPolygon);
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void NaN_and_infinite_vertices_are_left_out_with_a_diagnostic_and_the_dump_reads_back()
    {
        var gfx = Box(BrokenGfx, v => { v[1] = new Vector3(float.NaN, 0, 0); v[2] = new Vector3(0, float.PositiveInfinity, 0); return v; });
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx)), Bytes(gfx)));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("GfxObj 0x01000002: vertex id(s) 1, 2 have NaN or infinite coordinates", dump.Error);
            var json = Text(output, "dump/gfxobjs/0x01000002.bsp.json");
            var bsp = BspFileReader.Read(json);
            Assert.Equal([0, 3], bsp.Vertices.Select(v => v.Id));
            Assert.Null(Assert.Single(bsp.Polygons).Plane);
            Assert.All(bsp.Vertices, v => Assert.True(float.IsFinite(v.Position.X) && float.IsFinite(v.Position.Y) && float.IsFinite(v.Position.Z)));
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void An_infinite_placement_frame_is_a_diagnostic_and_the_shadow_file_reads_back_as_NaN()
    {
        var setup = SetupOf(Broken, BrokenGfx) with { PlacementFrames = [Records.PlacementAt(Placement.Resting, new Vector3(float.PositiveInfinity, 0, 0))] };
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(setup), Bytes(Box(BrokenGfx))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("warning: 0x02000002: non-finite: part 0 (GfxObj 0x01000002): non-finite position", dump.Error);
            var set = ShadowFileReader.Read(Text(output, "dump/setups/0x02000002.shadow.json"));
            Assert.True(float.IsNaN(Assert.Single(set.Shapes).LocalPosition.X));
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void A_NaN_splitting_plane_is_written_as_absent_and_compiles_with_a_repair()
    {
        var leaf = new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 1f), 0, 1, [0]);
        var root = new PhysicsBspNode(BspNodeType.BPIn, new Plane(new Vector3(float.NaN, 0, 1), 0), leaf, null, new Sphere(Vector3.Zero, 1f), 0, 0, []);
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx)), Bytes(Box(BrokenGfx, bsp: root))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("BSP node 0: splitting plane has NaN or infinite values; written as absent", dump.Error);
            var bsp = BspFileReader.Read(Text(output, "dump/gfxobjs/0x01000002.bsp.json"));
            Assert.Null(bsp.Nodes[0].Plane);
            Assert.Contains(CompiledBsp.Compile(bsp).Diagnostics, d => d.Code == CollisionDiagnosticCodes.MalformedNode);
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void A_BSP_200_levels_deep_is_extracted_whole()
    {
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx)), Bytes(Box(BrokenGfx, bsp: Chain(200)))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            var bsp = BspFileReader.Read(Text(output, "dump/gfxobjs/0x01000002.bsp.json"));
            Assert.Equal(200, bsp.Stats.MaxDepth);
            Assert.Equal(201, bsp.Nodes.Count);
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void A_BSP_deeper_than_the_limit_in_a_dat_leaves_the_part_out_with_a_diagnostic_and_the_batch_goes_on()
    {
        var (dump, batch, output) = DumpAndBatch(Portal(Bytes(SetupOf(Broken, BrokenGfx, HealthyGfxObj)), Bytes(Box(BrokenGfx, bsp: Chain(BspLimits.MaxDepth + 50)))));
        using (output)
        {
            Assert.Equal(0, dump.ExitCode);
            Assert.Contains("warning: 0x02000002: unreadable-gfxobj: part 0 (GfxObj 0x01000002) cannot be read", dump.Error);
            var set = ShadowFileReader.Read(Text(output, "dump/setups/0x02000002.shadow.json"));
            Assert.Equal([1], set.Shapes.Select(s => s.SourceIndex));
            BatchWentOn(batch, output);
        }
    }

    [Fact]
    public void Extraction_drops_what_lies_below_the_depth_limit_whatever_the_source()
    {
        var dump = BspExtractor.Extract(Box(BrokenGfx, bsp: Chain(BspLimits.MaxDepth + 50)))!;
        Assert.Equal(BspLimits.MaxDepth, dump.Stats.MaxDepth);
        Assert.Equal(BspLimits.MaxDepth + 1, dump.Nodes.Count);
        Assert.Contains(dump.Diagnostics, d => d.Contains($"deeper than {BspLimits.MaxDepth} levels"));
    }

    [Fact]
    public void Compiling_a_dump_100000_levels_deep_neither_overflows_the_stack_nor_walks_below_the_limit()
    {
        const int depth = 100_000;
        var nodes = new List<BspNode>(depth + 1);
        for (var i = 0; i < depth; i++)
            nodes.Add(new BspNode(i, BspNodeType.BPIn, new Plane(Vector3.UnitX, 0), new Sphere(Vector3.Zero, 10f), i + 1, null, 0, false, []));
        nodes.Add(new BspNode(depth, BspNodeType.Leaf, null, new Sphere(Vector3.Zero, 10f), null, null, 0, true, [0]));
        var box = BspExtractor.Extract(Box(BrokenGfx))!;
        var deep = box with { Nodes = nodes };

        var compiled = CompiledBsp.Compile(deep);

        Assert.Contains(compiled.Diagnostics, d => d.Message.Contains($"deeper than {BspLimits.MaxDepth} levels"));
        Assert.Empty(compiled.SolidCells);
        Assert.False(compiled.PruningIsConservative);
    }

    /// <summary>Every fault above in one dat: audit (with the collision chart) and chart go through all of them.</summary>
    [Fact]
    public void Audit_and_chart_go_through_every_fault_in_one_dat()
    {
        var leafNamingNothing = new PhysicsBspNode(BspNodeType.Leaf, default, null, null, new Sphere(Vector3.Zero, 1f), 0, 1, [0, 9]);
        var nanPlane = new PhysicsBspNode(BspNodeType.BPIn, new Plane(new Vector3(float.NaN, 0, 1), 0), leafNamingNothing, null, new Sphere(Vector3.Zero, 1f), 0, 0, []);
        var gfx = new[]
        {
            Box(0x01000010, polygonVertices: [0, 1, 2, 77]),
            Box(0x01000011, bsp: leafNamingNothing),
            Box(0x01000012, v => { v[1] = new Vector3(float.NaN, 0, 0); return v; }),
            Box(0x01000013, bsp: nanPlane),
            Box(0x01000014, bsp: Chain(200)),
            Box(0x01000015, bsp: Chain(BspLimits.MaxDepth + 50)),
        };
        var setups = gfx.Select((g, i) => Bytes(SetupOf(0x02000010u + (uint)i, g.Id, HealthyGfxObj))).ToList();
        setups.Add(Bytes(SetupOf(0x02000020, 0x0100FFFF)));
        setups.Add(Bytes(SetupOf(0x02000021, BrokenGfx) with { PlacementFrames = [Records.PlacementAt(Placement.Resting, new Vector3(float.PositiveInfinity, 0, 0))] }));
        var (_, shortSetup) = Bytes(SetupOf(0x02000022, BrokenGfx, HealthyGfxObj));
        setups.Add((0x02000022, shortSetup[..^40]));
        using var dat = Folder(Portal([.. setups, .. gfx.Select(Bytes), Bytes(Box(BrokenGfx))]));
        using var output = new TempDir();

        var audit = CliRun.Of("audit", "--dat", dat.Path, "--chart", "--format", "csv", "--out", Path.Combine(output.Path, "audit.csv"));
        var chart = CliRun.Of("chart", "--all", "--dat", dat.Path, "--out", Path.Combine(output.Path, "chart"), "--quiet", "--spacing", "0.5");

        Assert.True(audit.ExitCode == 0, audit.Error);
        Assert.True(chart.ExitCode == 0, chart.Error);
        Assert.Contains("skipped 1 (unreadable, see the warnings): 0x02000022", chart.Out);
        Assert.Contains("warning: 0x02000022: unreadable, skipped: ", chart.Error);
        var charted = File.ReadAllLines(Path.Combine(output.Path, "chart", "summary.csv"));
        // Nine decodable Setups (the healthy one, six with faulty parts, a missing part, an infinite frame), all charted.
        Assert.Contains(charted.Skip(1), l => l.StartsWith("retail,9,", StringComparison.Ordinal));
        Assert.DoesNotContain("   at ", audit.Error + chart.Error);
    }

    /// <summary>
    /// The dat stores exactly NumParts frames per placement (there is no frame count), so "fewer frames
    /// than parts" is a Setup whose bytes are one frame short: the reader reads NumParts frames anyway and
    /// the rest of the object shifts. Whatever it then decodes or refuses, the batch goes on.
    /// </summary>
    [Theory]
    [InlineData(-1)]
    [InlineData(+1)]
    public void A_placement_one_frame_short_or_long_in_the_bytes_never_stops_the_batch(int frameDelta)
    {
        var (_, bytes) = Bytes(SetupOf(Broken, BrokenGfx, HealthyGfxObj));
        const int secondFrame = 4 + 4 + 4 + 2 * 4 + 4 + 4 + 4 + 4 + 28; // header, parts, two empty tables, placement count and key, frame 0
        var frame = bytes.AsSpan(secondFrame, 28).ToArray();
        var edited = frameDelta < 0
            ? [.. bytes[..secondFrame], .. bytes[(secondFrame + 28)..]]
            : (byte[])[.. bytes[..(secondFrame + 28)], .. frame, .. bytes[(secondFrame + 28)..]];
        var (dump, batch, output) = DumpAndBatch(Portal((Broken, edited), Bytes(Box(BrokenGfx))));
        using (output)
        {
            // Found: the shifted bytes never decode (a hook count past the end, or bytes running out), so
            // dump refuses the Setup as a malformed dat (exit 3) and batch lists it as skipped, unreadable.
            Assert.Equal(3, dump.ExitCode);
            Assert.Contains("0x02000002", Assert.Single(dump.ErrorLines));
            BatchWentOn(batch, output);
            Assert.False(File.Exists(Path.Combine(output.Path, "batch/setups/0x02000002.shadow.json")));
            using var index = JsonDocument.Parse(Text(output, "batch/index.json"));
            var skipped = Assert.Single(index.RootElement.GetProperty("skipped").EnumerateArray());
            Assert.Equal("0x02000002", skipped.GetProperty("id").GetString());
            Assert.StartsWith("unreadable", skipped.GetProperty("reason").GetString());
        }
    }
}
