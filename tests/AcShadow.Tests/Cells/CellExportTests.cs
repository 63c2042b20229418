using System.Numerics;
using System.Text.Json;
using System.Text.Json.Serialization;
using AcShadow.Core.Cells;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Formats;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Cells;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cells;

/// <summary>
/// The sample landblock's cottage (ground floor 0xA9B40100, cellar 0xA9B40101) through batch, dump and
/// verify: cell files, acdream's cell files, scene.json's cell list, --no-cells, and planes that follow
/// the retail recipe to the bit.
/// </summary>
public class CellExportTests
{
    private const uint GroundFloor = 0xA9B40100, Cellar = 0xA9B40101;

    [Fact]
    public void A_landblock_batch_writes_each_cell_once_in_both_formats_and_lists_them_in_the_scene()
    {
        using var dir = new TempDir();
        var run = CliRun.Of("batch", "--landblock", "0xA9B4", "--format", "both", "--out", dir.Path, "--quiet");
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("2 cell(s)", run.Out);
        var files = dir.Files();
        Assert.Equal(["cells/0xA9B40100.cell.json", "cells/0xA9B40100.json", "cells/0xA9B40101.cell.json", "cells/0xA9B40101.json"],
            files.Where(f => f.StartsWith("cells/", StringComparison.Ordinal)));
        // The Setup placed inside the ground floor is exported like any placed Setup.
        Assert.Contains("setups/0x02003300.shadow.json", files);

        var set = FixtureSet.Open(dir.Path);
        Assert.Equal([GroundFloor, Cellar], set.Scene!.Cells.Select(c => c.Id));
        Assert.Equal([FileFormats.Cell.PathFor(GroundFloor), FileFormats.Cell.PathFor(Cellar)], set.Scene.Cells.Select(c => c.File));
        using var index = JsonDocument.Parse(File.ReadAllText(Path.Combine(dir.Path, "index.json")));
        var kinds = index.RootElement.GetProperty("files").EnumerateArray().Select(f => f.GetProperty("kind").GetString()).ToArray();
        Assert.Equal(2, kinds.Count(k => k == "cell"));
        Assert.Equal(2, kinds.Count(k => k == "acdream-cell"));
    }

    [Fact]
    public void The_ground_floor_cell_file_holds_frames_portals_visible_cells_and_the_object_inside()
    {
        var cell = CellFixture.Load(CommittedFixtures, GroundFloor).File;
        Assert.Equal(0x0D000100u, cell.EnvironmentId);
        Assert.Equal(0, cell.CellStructure);
        Assert.True(cell.SeenOutside);
        Assert.Equal(new Vector3(60, 60, 12), cell.LandblockFrame.Position);
        // Landblock 0xA9B4 starts at (0xA9 * 192, 0xB4 * 192) = (32448, 34560) in the world.
        Assert.Equal(new Vector3(32508, 34620, 12), cell.WorldFrame.Position);
        Assert.Equal(9, cell.Physics.Polygons.Count);
        Assert.All(cell.Physics.Polygons, p => Assert.NotNull(p.Plane));

        Assert.Equal(2, cell.Portals.Count);
        var door = cell.Portals[0];
        Assert.True(door.LeadsOutside);
        Assert.Equal(0xA9B4FFFFu, door.OtherCellId);
        Assert.Equal((ushort)PortalFlags.PortalSide, door.Flags);
        Assert.Equal(9, door.PolygonId);
        Assert.Equal(new Vector3(1, -2.5f, 2.2f), door.Vertices[2]);
        Assert.Equal(new Plane(0, -1, 0, -2.5f), door.Plane);
        var stairwell = cell.Portals[1];
        Assert.Equal(Cellar, stairwell.OtherCellId);
        Assert.False(stairwell.LeadsOutside);
        Assert.Equal([Cellar], cell.VisibleCells);

        var inside = Assert.Single(cell.Objects);
        Assert.Equal(0x02003300u, inside.Id);
        Assert.Equal(SceneObjectKind.Setup, inside.Kind);
        Assert.Equal("setups/0x02003300.shadow.json", inside.File);
        Assert.Equal(new Vector3(62, 57.5f, 12), inside.LandblockFrame.Position);
    }

    /// <summary>
    /// The retail recipe (CPolygon::make_plane) worked by hand in float32 for two of the cottage's polygons,
    /// each step rounded to float as the client rounds it.
    /// Tilted ceiling (-3,-2.5,3) (-3,2.5,3.5) (3,2.5,3.5) (3,-2.5,3): fan edges from v0 are (0,5,0.5),
    /// (6,5,0.5), (6,0,0); cross((0,5,0.5),(6,5,0.5)) = (0,3,-30) and cross((6,5,0.5),(6,0,0)) = (0,3,-30), sum
    /// (0,6,-60); |n|² = 3636, √ = 60.299255 (0x42713270); n = (0, 6/60.299255, -60/60.299255) = (0,
    /// 0x3DCBC89B, 0xBF7EBAC1); each vertex's n·v is -3.2338707 in float, the four summed in order -12.935483,
    /// / 4 and negated: d = 3.2338707 (0x404EF7BD), where the same plane worked in double and rounded once at
    /// the end gives 3.233871 (0x404EF7BE).
    /// Ramp (-1,1,-3) (3,1,0) (3,2.5,0) (-1,2.5,-3): crosses (-4.5,0,6) twice, sum (-9,0,12), length 15, n =
    /// (-0.6, 0, 0.8) = (0xBF19999A, 0, 0x3F4CCCCD); each n·v is -1.8000001 in float, their sum -7.2000003, so d =
    /// 1.8000001 (0x3FE66667) where the exact plane has 1.8 (0x3FE66666).
    /// </summary>
    [Theory]
    [InlineData(GroundFloor, 8, 0x00000000u, 0x3DCBC89Bu, 0xBF7EBAC1u, 0x404EF7BDu)]
    [InlineData(Cellar, 7, 0xBF19999Au, 0x00000000u, 0x3F4CCCCDu, 0x3FE66667u)]
    public void Cell_polygon_planes_are_the_retail_recipes_bits(uint cellId, int polygonId, uint nx, uint ny, uint nz, uint d)
    {
        var cell = CellFixture.Load(CommittedFixtures, cellId).File;
        var polygon = cell.Physics.Polygons.Single(p => p.Id == polygonId);
        var plane = polygon.Plane!.Value;
        Assert.Equal([nx, ny, nz, d], new[] { plane.Normal.X, plane.Normal.Y, plane.Normal.Z, plane.D }.Select(BitConverter.SingleToUInt32Bits));
        // The same bits from the library's recipe over the file's own vertices.
        var points = polygon.VertexIds.Select(v => cell.Physics.Vertices.Single(x => x.Id == v).Position).ToArray();
        Assert.Equal(plane, PolygonPlane.Compute(points));
    }

    [Fact]
    public void The_acdream_cell_file_loads_with_acdreams_record_and_matches_the_canonical_one()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("dump", "--cell", "0xA9B40100", "--format", "both", "--out", dir.Path).ExitCode);
        var dump = JsonSerializer.Deserialize(File.ReadAllBytes(Path.Combine(dir.Path, FileFormats.AcdreamCell.PathFor(GroundFloor))), AcdreamCellJson.Default.CellDump)!;
        var canonical = CellFileReader.Read(File.ReadAllText(Path.Combine(dir.Path, FileFormats.Cell.PathFor(GroundFloor))));
        Assert.Equal(GroundFloor, dump.CellId);
        var world = dump.WorldTransform.ToMatrix();
        var inverse = dump.InverseWorldTransform.ToMatrix();
        // acdream's own check on its captured cells: the origin through WorldTransform is the cell's landblock origin.
        Assert.Equal(new Vector3(60, 60, 12), Vector3.Transform(Vector3.Zero, world));
        // A cell-local point goes out and back (and matches the canonical frame's rotation).
        var local = new Vector3(1, -2.5f, 2.2f);
        var out_ = Vector3.Transform(local, world);
        Assert.True(Vector3.Distance(out_, new Vector3(62.5f, 61, 14.2f)) < 1e-5f, $"{out_}");
        Assert.True(Vector3.Distance(Vector3.Transform(out_, inverse), local) < 1e-5f);
        Assert.Equal(canonical.Physics.Polygons.Select(p => p.Id), dump.ResolvedPolygons.Select(p => (int)p.Id));
        Assert.Equal([(ushort)9, (ushort)10], dump.PortalPolygons.Select(p => p.Id));
        Assert.Equal([new PortalDump(0xFFFF, 9, 2), new PortalDump(0x0101, 10, 1)], dump.Portals);
        Assert.Equal([Cellar], dump.VisibleCellIds);
        Assert.True(File.Exists(Path.Combine(dir.Path, "setups/0x02003300.shadow.json")));
    }

    [Fact]
    public void No_cells_writes_the_objects_only_and_the_index_says_so_for_verify()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--landblock", "0xA9B4", "--no-cells", "--out", dir.Path, "--quiet").ExitCode);
        Assert.DoesNotContain(dir.Files(), f => f.StartsWith("cells/", StringComparison.Ordinal));
        Assert.DoesNotContain(dir.Files(), f => f == "setups/0x02003300.shadow.json");
        Assert.Empty(FixtureSet.Open(dir.Path).Scene!.Cells);
        using var index = JsonDocument.Parse(File.ReadAllText(Path.Combine(dir.Path, "index.json")));
        Assert.False(index.RootElement.GetProperty("inputs").GetProperty("selection").GetProperty("cells").GetBoolean());
        Assert.Equal(0, CliRun.Of("verify", "--fixtures", dir.Path).ExitCode);
    }

    [Fact]
    public void Verify_covers_the_cell_files()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--landblock", "0xA9B4", "--out", dir.Path, "--quiet").ExitCode);
        var path = Path.Combine(dir.Path, FileFormats.Cell.PathFor(Cellar));
        File.WriteAllText(path, File.ReadAllText(path).Replace("\"seenOutside\": false", "\"seenOutside\": true"));
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains($"changed {FileFormats.Cell.PathFor(Cellar)}", run.Out);
    }

    [Theory]
    [InlineData(new[] { "dump", "--cell", "0xA9B40040" }, 2, "outdoor land cells")]
    [InlineData(new[] { "dump", "--cell", "0xA9B40102" }, 4, "is not in")]
    [InlineData(new[] { "dump", "--cell", "0xA9B40100", "--setup", "0x020019FF" }, 2, "exactly one of")]
    [InlineData(new[] { "batch", "--doors", "--no-cells", "--out", "never" }, 2, "add --landblock")]
    [InlineData(new[] { "batch", "--landblock", "0xA9B4", "--cells", "--no-cells", "--out", "never" }, 2, "contradict")]
    public void Bad_cell_arguments_are_one_clear_line(string[] args, int code, string message)
    {
        var run = CliRun.Of(args);
        Assert.Equal(code, run.ExitCode);
        Assert.Contains(message, run.Error);
        Assert.False(Directory.Exists("never"));
    }

    [Fact]
    public void Cell_matrices_are_the_rigid_frame_and_its_inverse()
    {
        var frame = new Frame(new Vector3(10, -4, 2), Quaternion.Normalize(new Quaternion(0.1f, 0.7f, -0.2f, 0.6f)));
        var world = CellMatrices.World(frame);
        var inverse = CellMatrices.Inverse(frame);
        var p = new Vector3(1.5f, -2, 3);
        Assert.True(Vector3.Distance(Vector3.Transform(p, world), Vector3.Transform(p, frame.Rotation) + frame.Position) < 1e-5f);
        Assert.True(Vector3.Distance(Vector3.Transform(Vector3.Transform(p, world), inverse), p) < 1e-5f);
        var numerics = Matrix4x4.CreateFromQuaternion(frame.Rotation) * Matrix4x4.CreateTranslation(frame.Position);
        for (var i = 0; i < 4; i++)
            for (var j = 0; j < 4; j++)
                Assert.True(MathF.Abs(numerics[i, j] - world[i, j]) < 1e-6f, $"M{i + 1}{j + 1}");
    }

    [Fact]
    public void Cell_matrices_carry_the_client_s_matrix_entries()
    {
        // The dat's quarter turn about z (W = Z = 0.70710677f): Frame::cache gives m0 = m4 = 4817239 * 2^-47 (0x331302AE),
        // m1 = 0.99999994 (0x3F7FFFFF), m3 = -m1, m8 = 1 (worked in ClientFrameMatrixTests); M's rows are m_fl2gv's rows.
        // System.Numerics' float formula gives 5.9604645e-08 (0x33800000) for M11 instead.
        var half = BitConverter.UInt32BitsToSingle(0x3F3504F3);
        var world = CellMatrices.World(new Frame(new Vector3(60f, 60f, 12f), new Quaternion(0f, 0f, half, half)));
        uint[] expected = [0x331302AE, 0x3F7FFFFF, 0, 0xBF7FFFFF, 0x331302AE, 0, 0, 0, 0x3F800000];
        uint[] actual = [.. new[] { world.M11, world.M12, world.M13, world.M21, world.M22, world.M23, world.M31, world.M32, world.M33 }.Select(BitConverter.SingleToUInt32Bits)];
        Assert.Equal(expected, actual);
    }

    private static string CommittedFixtures => AcShadow.Tests.Fixtures.CommittedFixturesTests.RepositoryFixtures();
}

// acdream's CellDump record and its parts (AcDream.Core.Physics): names and types as acdream declares them.
public sealed record Matrix4x4Dto(
    float M11, float M12, float M13, float M14, float M21, float M22, float M23, float M24,
    float M31, float M32, float M33, float M34, float M41, float M42, float M43, float M44)
{
    public Matrix4x4 ToMatrix() => new(M11, M12, M13, M14, M21, M22, M23, M24, M31, M32, M33, M34, M41, M42, M43, M44);
}

public sealed record PortalDump(ushort OtherCellId, ushort PolygonId, ushort Flags);

public sealed record CellDump(uint CellId, Matrix4x4Dto WorldTransform, Matrix4x4Dto InverseWorldTransform,
    IReadOnlyList<Acdream.AcdreamPolygon> ResolvedPolygons, IReadOnlyList<Acdream.AcdreamPolygon> PortalPolygons,
    IReadOnlyList<PortalDump> Portals, IReadOnlyList<uint> VisibleCellIds);

[JsonSourceGenerationOptions(UnmappedMemberHandling = JsonUnmappedMemberHandling.Disallow)]
[JsonSerializable(typeof(CellDump))]
internal sealed partial class AcdreamCellJson : JsonSerializerContext;
