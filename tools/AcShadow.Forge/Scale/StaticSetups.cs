using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The scale spec's statics: 1-30 physics parts stacked with jitter (few parts common, many rare), one in
/// eight extra parts drawing-only (a banner on a wall: no shape from it), one in five scaled per part, one
/// in ten without the HasPhysicsBsp flag; placed Resting mostly, Default or Other sometimes.
/// </summary>
internal static class StaticSetups
{
    public static List<SetupSpec> Generate(Random random, ScaleIds ids, PartPools pools, int count)
    {
        var statics = new List<SetupSpec>(count);
        for (var s = 0; s < count; s++)
        {
            var partCount = PartCount(random, 1);
            var parts = Enumerable.Range(0, partCount).Select(k => k > 0 && random.Next(8) == 0 ? pools.NextDrawing() : pools.NextPhysics()).ToArray();
            var frames = new List<FrameSpec>();
            var z = 0.0;
            foreach (var part in parts)
            {
                frames.Add(Frame(Range(random, -1, 1), Range(random, -1, 1), z, random.Next(24) * 15));
                z += part.Size * 0.5;
            }
            var extent = parts.Max(p => p.Size) + 1.5;
            var placement = random.Next(10) switch { 0 => "Default", 1 => "Other", _ => "Resting" };
            statics.Add(new SetupSpec
            {
                Id = Hex(ids.NewSetup()),
                Parts = parts.Select(p => Hex(p.Id)).ToArray(),
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?> { [placement] = frames },
                DefaultScale = random.Next(5) == 0 ? parts.Select(_ => new[] { Range(random, 0.5, 2), Range(random, 0.5, 2), Range(random, 0.5, 2) }).ToArray() : null,
                Radius = Math.Round(extent, 3),
                Height = Math.Round(z + parts[^1].Size, 3),
                Flags = random.Next(10) == 0 ? [] : ["HasPhysicsBsp"],
            });
        }
        return statics;
    }
}
