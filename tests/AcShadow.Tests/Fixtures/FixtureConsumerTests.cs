using System.Numerics;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Fixtures;

/// <summary>
/// What a collision project does with the committed fixtures: load a Setup's shadow file and the BSP
/// dumps it references, and query them. It must get exactly the answers the tool gets from the dat.
/// </summary>
public class FixtureConsumerTests
{
    [Theory]
    [InlineData(0x020019FFu)]
    [InlineData(0x02003000u)]
    [InlineData(0x02000281u)]
    public void Shadow_file_and_bsp_dumps_answer_like_the_dat(uint setupId)
    {
        var fixtures = CommittedFixturesTests.RepositoryFixtures();
        var shadowPath = Path.Combine(fixtures, FileFormats.Shadow.PathFor(setupId));
        var fromJson = ShadowFileReader.Read(File.ReadAllText(shadowPath));
        var dumps = fromJson.Shapes.Where(s => s.GfxObjId is not null && s.CollisionType == CollisionType.Bsp)
            .Select(s => s.GfxObjId!.Value).Distinct()
            .ToDictionary(id => id, id => CompiledBsp.Compile(BspFileReader.Read(
                File.ReadAllText(Path.Combine(fixtures, FileFormats.Bsp.PathFor(id))))));
        var consumer = ObjectOverlapQuery.Create(fromJson, id => dumps.GetValueOrDefault(id));

        using var dat = SampleDat.OpenPortal();
        var set = ShadowShapeBuilder.Build(dat.ReadSetup(setupId)!, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail));
        var tool = ObjectOverlapQuery.Create(set, id => dat.ReadGfxObj(id) is { } g && AcShadow.Core.Bsp.BspExtractor.Extract(g) is { } d ? CompiledBsp.Compile(d) : null);

        var random = new Random((int)setupId);
        var blocked = 0;
        for (var i = 0; i < 20000; i++)
        {
            var c = new Vector3(Next(-3, 3), Next(-3, 3), Next(-0.5f, 3));
            var r = Next(0.05f, 0.8f);
            var expected = tool.Overlaps(c, r);
            Assert.Equal(expected, consumer.Overlaps(c, r));
            if (expected) blocked++;
        }
        Assert.InRange(blocked, 100, 19900); // the probes straddle the object, so both answers occur

        float Next(float lo, float hi) => lo + (float)random.NextDouble() * (hi - lo);
    }
}
