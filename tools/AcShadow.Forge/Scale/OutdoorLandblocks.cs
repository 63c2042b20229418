using AcShadow.Forging;
using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The scale spec's landblocks as seen outdoors: one per 200 Setups (at least one), each placing 10-30
/// objects (the first, <see cref="ScaleSpecGenerator.BusyLandblockObjects"/>) anywhere in its 192 m square,
/// one in five a bare GfxObj and the rest Setups, and up to three buildings.
/// </summary>
internal static class OutdoorLandblocks
{
    public static List<LandblockSpec> Generate(Random random, int setups, IReadOnlyList<string> placeable, IReadOnlyList<uint> bareModels)
    {
        var landblocks = new List<LandblockSpec>();
        for (var l = 0; l < Math.Max(1, setups / 200); l++)
        {
            var id = (uint)(((l % 254) << 24) | ((l / 254) << 16) | 0xFFFE);
            // The first landblock is a busy one (as a town's), so a scene compile is measured at scale.
            var objects = Enumerable.Range(0, l == 0 ? ScaleSpecGenerator.BusyLandblockObjects : random.Next(10, 31)).Select(_ =>
            {
                var model = random.Next(5) == 0 ? Hex(bareModels[random.Next(bareModels.Count)]) : placeable[random.Next(placeable.Count)];
                return new StabSpec { Id = model, Origin = [Range(random, 0, 192), Range(random, 0, 192), Range(random, 0, 40)], Orientation = SampleSpecAuthor.Z(random.Next(360)) };
            }).ToArray();
            var buildings = Enumerable.Range(0, random.Next(0, 4)).Select(_ => new BuildingSpec
            {
                ModelId = Hex(bareModels[random.Next(bareModels.Count)]),
                Origin = [Range(random, 0, 192), Range(random, 0, 192), Range(random, 0, 40)],
                Orientation = SampleSpecAuthor.Z(random.Next(4) * 90),
                NumLeaves = random.Next(1, 8),
            }).ToArray();
            landblocks.Add(new LandblockSpec { Id = Hex(id), Objects = objects, Buildings = buildings });
        }
        return landblocks;
    }
}
