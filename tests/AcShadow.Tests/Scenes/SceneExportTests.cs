using System.Numerics;
using System.Text.Json;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Scenes;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;
using static AcShadow.Tests.Batch.BatchRuns;

namespace AcShadow.Tests.Scenes;

public class SceneExportTests
{
    private const string ScenePath = "scene.json";

    [Fact]
    public void A_scene_writes_only_what_it_places_each_once()
    {
        // Objects only: the cells' own files are CellExportTests' business.
        var (run, dir) = RunBatch("--landblock", "0xA9B4", "--no-cells");
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            var expected = new SortedSet<string>(StringComparer.Ordinal) { "index.json", ScenePath };
            foreach (var setup in new[] { "0x020019FF", "0x02003000" })
            {
                var shadow = $"setups/{setup}.shadow.json";
                expected.Add(shadow);
                using var doc = JsonDocument.Parse(Text(dir, shadow));
                foreach (var shape in doc.RootElement.GetProperty("shapes").EnumerateArray())
                    if (shape.TryGetProperty("bsp", out var bsp)) expected.Add(bsp.GetString()!.Replace("../", ""));
            }
            expected.Add("gfxobjs/0x01003002.bsp.json"); // the bare column
            expected.Add("gfxobjs/0x01005000.bsp.json"); // the house building
            Assert.Equal(expected, dir.Files());
            Assert.Contains("2 setup(s)", run.Out);
            Assert.Contains("1 scene(s)", run.Out);
        }
    }

    [Fact]
    public void Scene_file_lists_every_placed_object_with_both_frames_and_its_file()
    {
        var (run, dir) = RunBatch("--landblock", "0xA9B4");
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            using var doc = JsonDocument.Parse(Text(dir, ScenePath));
            var root = doc.RootElement;
            Assert.Equal("acshadow.scene/1", root.GetProperty("format").GetString());
            Assert.Equal([32448d, 34560d, 0d], root.GetProperty("worldOrigin").EnumerateArray().Select(e => e.GetDouble()));
            var objects = root.GetProperty("objects").EnumerateArray().ToArray();
            Assert.Equal(["0x020019FF", "0x01003002", "0x02003000", "0x01005000"], objects.Select(o => o.GetProperty("id").GetString()));
            Assert.Equal(["object", "object", "object", "building"], objects.Select(o => o.GetProperty("placedBy").GetString()));
            Assert.Equal(["setup", "gfxObj", "setup", "gfxObj"], objects.Select(o => o.GetProperty("kind").GetString()));

            var door = objects[0];
            Assert.Equal("[136, 108, 12]", door.GetProperty("landblockFrame").GetProperty("origin").GetRawText().Replace("\n", ""));
            Assert.Equal([32584d, 34668d, 12d], door.GetProperty("worldFrame").GetProperty("origin").EnumerateArray().Select(e => e.GetDouble()));
            Assert.Equal(door.GetProperty("landblockFrame").GetProperty("orientation").GetRawText(), door.GetProperty("worldFrame").GetProperty("orientation").GetRawText());
            Assert.False(door.TryGetProperty("shapes", out _));

            foreach (var o in objects)
            {
                var file = o.GetProperty("file").GetString()!;
                Assert.DoesNotContain("..", file);
                Assert.True(File.Exists(Path.Combine(dir.Path, file)), $"{file} is not where the scene says");
            }
            foreach (var bare in objects.Where(o => o.GetProperty("kind").GetString() == "gfxObj"))
            {
                var shape = Assert.Single(bare.GetProperty("shapes").EnumerateArray());
                Assert.Equal("bsp", shape.GetProperty("collisionType").GetString());
                Assert.Equal(bare.GetProperty("id").GetString(), shape.GetProperty("gfxObjId").GetString());
                Assert.Equal(bare.GetProperty("file").GetString(), shape.GetProperty("bsp").GetString());
                Assert.Equal("[0, 0, 0]", shape.GetProperty("localPosition").GetRawText());
            }
            var summary = root.GetProperty("summary");
            Assert.Equal(4, summary.GetProperty("resolved").GetInt32());
            Assert.Equal(0, summary.GetProperty("unresolved").GetInt32());
        }
    }

    [Fact]
    public void Unresolvable_placements_are_listed_and_skipped_not_fatal()
    {
        using var dats = SampleDat.WriteToTempFolder();
        using var cellDir = new TempDir();
        var cellPath = Path.Combine(cellDir.Path, "client_cell_1.dat");
        var turned = new Frame(new Vector3(1.5f, 2.25f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.5f));
        var info = new LandBlockInfo(0x0102FFFE, 0,
            [
                new Stab(0x0200ABCD, turned),     // a Setup the portal dat lacks
                new Stab(0x0100ABCD, turned),     // a GfxObj the portal dat lacks
                new Stab(0x01001000, turned),     // drawing only: resolved, no shapes, no dump
                new Stab(0x03000001, turned),     // neither a Setup nor a GfxObj
                new Stab(0x020019FF, Frame.Identity),
            ],
            [], []);
        var w = new DatBinaryWriter();
        info.Write(w);
        File.WriteAllBytes(cellPath, DatArchiveWriter.Write(new Dictionary<uint, byte[]> { [info.Id] = w.ToArray() }, new DatArchiveWriter.Options(DatFileKind.Cell)));

        var (run, dir) = RunBatch("--landblock", "0x0102", "--dat", dats.Path, "--cell-dat", cellPath);
        using (dir)
        {
            Assert.Equal(0, run.ExitCode);
            Assert.DoesNotContain("gfxobjs/0x01001000.bsp.json", dir.Files());
            using var doc = JsonDocument.Parse(Text(dir, "scene.json"));
            var objects = doc.RootElement.GetProperty("objects").EnumerateArray().ToArray();
            Assert.Equal(JsonValueKind.Null, objects[0].GetProperty("file").ValueKind);
            Assert.Contains("Setup 0x0200ABCD: not in the dat", objects[0].GetProperty("diagnostics").GetRawText());
            Assert.Equal(JsonValueKind.Null, objects[1].GetProperty("file").ValueKind);
            Assert.Equal(JsonValueKind.Null, objects[2].GetProperty("file").ValueKind);
            Assert.Empty(objects[2].GetProperty("shapes").EnumerateArray());
            Assert.Contains("no-shapes", objects[2].GetProperty("diagnostics").GetRawText());
            Assert.Equal("other", objects[3].GetProperty("kind").GetString());
            Assert.Equal("setups/0x020019FF.shadow.json", objects[4].GetProperty("file").GetString());
            Assert.Equal(2, doc.RootElement.GetProperty("summary").GetProperty("resolved").GetInt32());
            Assert.Equal(3, doc.RootElement.GetProperty("summary").GetProperty("unresolved").GetInt32());

            using var index = JsonDocument.Parse(Text(dir, "index.json"));
            var skipped = index.RootElement.GetProperty("skipped").EnumerateArray()
                .Select(s => (s.GetProperty("id").GetString(), s.GetProperty("from")[0].GetString())).ToArray();
            Assert.Equal([("0x0100ABCD", "landblock"), ("0x0200ABCD", "landblock")], skipped);
        }
    }

    [Fact]
    public void World_origin_adds_the_float_as_written_not_its_binary_expansion()
    {
        var landblock = LandblockCoordinates.Of(0xA9B4FFFE);
        var (x, y, z) = WorldFrame.Origin(landblock, new Frame(new Vector3(132f, 103.9f, -0f), Quaternion.Identity));
        Assert.Equal(32580d, x);
        Assert.Equal(34663.9d, y);
        Assert.Equal(0d, z);
    }

    [Fact]
    public void Bare_gfxobj_shape_comes_from_the_builder_as_a_one_part_object()
    {
        using var portal = SampleDat.OpenPortal();
        var gfx = portal.ReadGfxObj(0x01003002)!;
        var set = BareGfxObjShape.Build(gfx, portal.ReadGfxObj, new Core.Shapes.ShapeBuildOptions(ShapePolicy.Retail, 2f));
        var shape = Assert.Single(set.Shapes);
        Assert.Equal(0x01003002u, shape.GfxObjId);
        Assert.Equal(2f, shape.Scale);
        Assert.Equal(gfx.PhysicsBsp!.BoundingSphere.Radius * 2f, shape.Radius);
        Assert.Empty(set.Diagnostics);
    }
}
