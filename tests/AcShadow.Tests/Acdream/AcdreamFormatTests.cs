using System.Numerics;
using System.Text.Json.Serialization;
using System.Text.Json;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Acdream;

/// <summary>
/// `--format acdream`: the door's parts as acdream's GfxObj fixtures. The files are read the way acdream's
/// tests read them: System.Text.Json into records with acdream's property names and types (uint id,
/// ushort polygon ids, int sides type), case-sensitive; unknown members are refused here, which is
/// stricter than acdream. Source-generated, so no reflection.
/// </summary>
public class AcdreamFormatTests
{
    [Fact]
    public void Door_parts_load_with_acdreams_field_names()
    {
        using var outDir = new TempDir();
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--format", "acdream", "--out", outDir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Equal(["gfxobjs/0x010044B5.gfxobj.json", "gfxobjs/0x010044B6.gfxobj.json"], outDir.Files());

        foreach (var id in new uint[] { 0x010044B5, 0x010044B6 })
        {
            var gfx = JsonSerializer.Deserialize(File.ReadAllBytes(Path.Combine(outDir.Path, FileFormats.AcdreamGfxObj.PathFor(id))), AcdreamJson.Default.GfxObjFixture)!;
            Assert.Equal(id, gfx.GfxObjId);
            var canonical = BspFileReader.Read(File.ReadAllText(Path.Combine(CommittedFixtures, FileFormats.Bsp.PathFor(id))));
            Assert.Equal(canonical.BoundingSphere.Center, Vec(gfx.BoundingSphereOrigin));
            Assert.Equal(canonical.BoundingSphere.Radius, gfx.BoundingSphereRadius);
            Assert.Equal(canonical.Polygons.Where(p => p.Plane is not null).Select(p => p.Id), gfx.ResolvedPolygons.Select(p => (int)p.Id));
            foreach (var polygon in gfx.ResolvedPolygons)
            {
                var source = canonical.Polygons.Single(p => p.Id == polygon.Id);
                Assert.Equal(source.VertexIds.Count, polygon.NumPoints);
                Assert.Equal(polygon.NumPoints, polygon.Vertices.Count);
                Assert.Equal((int)source.SidesType, polygon.SidesType);
                Assert.Equal(source.Plane!.Value.Normal, Vec(polygon.Plane.Normal));
                Assert.Equal(source.Plane.Value.D, polygon.Plane.D);
                // Vertices in the polygon's own order: each is the canonical vertex its id names.
                Assert.Equal(source.VertexIds.Select(v => canonical.Vertices.Single(x => x.Id == v).Position), polygon.Vertices.Select(Vec));
                foreach (var v in polygon.Vertices)
                    Assert.InRange(Vector3.Dot(Vec(polygon.Plane.Normal), Vec(v)) + polygon.Plane.D, -1e-4f, 1e-4f);
            }
        }
    }

    [Fact]
    public void Both_writes_canonical_and_acdream_files_and_batch_lists_them_in_the_index_and_verifies()
    {
        using var outDir = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--all", "--format", "both", "--out", outDir.Path, "--quiet").ExitCode);
        var files = outDir.Files();
        var bsp = files.Where(f => f.EndsWith(".bsp.json")).ToArray();
        Assert.NotEmpty(bsp);
        Assert.Equal(bsp.Select(f => f.Replace(".bsp.json", ".gfxobj.json")), files.Where(f => f.EndsWith(".gfxobj.json")));
        using var index = JsonDocument.Parse(File.ReadAllText(Path.Combine(outDir.Path, "index.json")));
        Assert.Equal("both", index.RootElement.GetProperty("inputs").GetProperty("formats").GetString());
        var acdream = index.RootElement.GetProperty("files").EnumerateArray().Where(f => f.GetProperty("kind").GetString() == "acdream").ToArray();
        Assert.Equal(bsp.Length, acdream.Length);
        var verify = CliRun.Of("verify", "--fixtures", outDir.Path);
        Assert.True(verify.ExitCode == 0, verify.Out + verify.Error);

        File.AppendAllText(Path.Combine(outDir.Path, bsp[0].Replace(".bsp.json", ".gfxobj.json")), " ");
        Assert.Equal(5, CliRun.Of("verify", "--fixtures", outDir.Path).ExitCode);
    }

    [Fact]
    public void Acdream_output_is_byte_identical_across_runs_and_jobs()
    {
        using var one = new TempDir();
        using var two = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--all", "--format", "acdream", "--jobs", "1", "--out", one.Path, "--quiet").ExitCode);
        Assert.Equal(0, CliRun.Of("batch", "--all", "--format", "acdream", "--jobs", "4", "--out", two.Path, "--quiet").ExitCode);
        Assert.Equal(one.Files(), two.Files());
        Assert.DoesNotContain(one.Files(), f => f.EndsWith(".bsp.json") || f.EndsWith(".shadow.json"));
        foreach (var f in one.Files())
            Assert.Equal(File.ReadAllBytes(Path.Combine(one.Path, f)), File.ReadAllBytes(Path.Combine(two.Path, f)));
    }

    [Fact]
    public void An_unknown_format_is_a_usage_error()
    {
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--format", "acdreem");
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("--format: 'acdreem' is not a format: use canonical (the default), acdream or both", run.Error);
    }

    private static string CommittedFixtures => Fixtures.CommittedFixturesTests.RepositoryFixtures();

    private static Vector3 Vec(Xyz v) => new(v.X, v.Y, v.Z);
}

public sealed record Xyz(float X, float Y, float Z);
public sealed record AcdreamPlane(Xyz Normal, float D);
public sealed record AcdreamPolygon(ushort Id, int NumPoints, int SidesType, AcdreamPlane Plane, IReadOnlyList<Xyz> Vertices);
public sealed record GfxObjFixture(uint GfxObjId, Xyz BoundingSphereOrigin, float BoundingSphereRadius, IReadOnlyList<AcdreamPolygon> ResolvedPolygons);

[JsonSourceGenerationOptions(UnmappedMemberHandling = JsonUnmappedMemberHandling.Disallow, RespectRequiredConstructorParameters = true)]
[JsonSerializable(typeof(GfxObjFixture))]
internal sealed partial class AcdreamJson : JsonSerializerContext;
