using System.Numerics;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fixtures;

/// <summary>The AcShadow.Fixtures entry points over the committed fixtures, and their refusals.</summary>
public class FixtureLibraryTests
{
    private static FixtureSet Committed => FixtureSet.Open(CommittedFixturesTests.RepositoryFixtures());

    [Fact]
    public void Index_lists_every_file_in_the_folder()
    {
        var index = Committed.Index!;
        var onDisk = Directory.GetFiles(Committed.Folder, "*.json", SearchOption.AllDirectories)
            .Select(f => Path.GetRelativePath(Committed.Folder, f).Replace('\\', '/')).Where(p => p != "index.json").Order().ToArray();
        Assert.Equal(onDisk, index.Files.Select(f => f.Path).Order().ToArray());
        Assert.Equal(19, index.OfKind(FixtureKind.Shadow).Count()); // the sample's 19 Setups
        Assert.Single(index.OfKind(FixtureKind.Movement));
    }

    [Fact]
    public void Scene_places_each_object_at_its_world_frame()
    {
        var scene = Committed.Scene!;
        Assert.Equal(0xA9B4FFFEu, scene.LandblockId);
        var placed = Committed.PlaceScene();
        Assert.Equal(scene.Objects.Count(o => o.File is not null), placed.Count);
        // Each placed object blocks a small sphere at the world position of its first shape's bounding-sphere centre.
        foreach (var (o, p) in scene.Objects.Where(o => o.File is not null).Zip(placed))
        {
            Assert.Equal(o.WorldFrame.Position, p.Position);
            var shape = p.Fixture.Shadow.Shapes.First(s => s.LocalSphere is not null);
            var probe = p.Position + Vector3.Transform(shape.LocalSphere!.Value.Center, p.Rotation);
            Assert.True(p.Overlaps(probe, shape.LocalSphere.Value.Radius), $"object {o.Index} (0x{o.Id:X8})");
            Assert.False(p.Overlaps(probe + new Vector3(0, 0, 1000), 0.5f));
        }
    }

    [Fact]
    public void The_readme_example_blocks_a_sphere_in_the_doorway_and_not_one_beside_it()
    {
        var door = Committed.Setup(0x020019FF)
            .PlaceAt(new Vector3(32584f, 34668f, 12f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2));
        Assert.True(door.Overlaps(worldCenter: new Vector3(32584f, 34668.6f, 13f), radius: 0.5f));
        Assert.False(door.Overlaps(worldCenter: new Vector3(32587f, 34672.1f, 13f), radius: 0.5f));
        Assert.Throws<ArgumentException>(() => Committed.Setup(0x020019FF).PlaceAt(Vector3.Zero, default));
    }

    [Theory]
    [InlineData("setups/0x020019FF.shadow.json", "acshadow.shadow/1", "a version this library does not read (it reads \"acshadow.shadow/2\")")]
    [InlineData("setups/0x020019FF.shadow.json", "acshadow.bsp/1", "is not \"acshadow.shadow/2\"; wrong kind of file?")]
    [InlineData("gfxobjs/0x010044B5.bsp.json", "acshadow.bsp/9", "a version this library does not read (it reads \"acshadow.bsp/1\")")]
    public void An_unknown_format_version_is_refused_by_name(string file, string format, string expected)
    {
        using var dir = new TempDir();
        foreach (var f in new[] { "setups/0x020019FF.shadow.json", "gfxobjs/0x010044B5.bsp.json", "gfxobjs/0x010044B6.bsp.json" })
        {
            var target = Path.Combine(dir.Path, f);
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            var text = File.ReadAllText(Path.Combine(Committed.Folder, f));
            File.WriteAllText(target, f == file ? text.Replace(FileFormats.Shadow.Format, format).Replace(FileFormats.Bsp.Format, format) : text);
        }
        var e = Assert.Throws<FormatException>(() => SetupFixture.Load(dir.Path, 0x020019FF));
        Assert.Contains(expected, e.Message);
        Assert.Contains(Path.Combine(dir.Path, file), e.Message);
    }

    [Fact]
    public void A_missing_bsp_dump_is_named_with_the_fix()
    {
        using var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "setups"));
        File.Copy(Path.Combine(Committed.Folder, "setups/0x020019FF.shadow.json"), Path.Combine(dir.Path, "setups/0x020019FF.shadow.json"));
        var e = Assert.Throws<FileNotFoundException>(() => SetupFixture.Load(dir.Path, 0x020019FF));
        Assert.Contains("names GfxObj 0x010044B5", e.Message);
        Assert.Contains("copy the whole output folder", e.Message);
    }
}
