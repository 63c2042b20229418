using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>The scale spec's items: one drawing-only part, collided with one or two Spheres only.</summary>
internal static class ItemSetups
{
    public static List<SetupSpec> Generate(Random random, ScaleIds ids, PartPools pools, int count)
    {
        var items = new List<SetupSpec>(count);
        for (var i = 0; i < count; i++)
        {
            var part = pools.NextDrawing();
            var spheres = Enumerable.Range(0, random.Next(1, 3))
                .Select(k => new SphereSpec { Center = [0, 0, part.Size / 2 + k * 0.1], Radius = Math.Round(part.Size / 2, 3) }).ToArray();
            items.Add(new SetupSpec
            {
                Id = Hex(ids.NewSetup()),
                Parts = [Hex(part.Id)],
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?> { ["Default"] = [Frame(0, 0, 0, 0)] },
                Spheres = spheres,
                Radius = Math.Round(part.Size, 3),
                Height = Math.Round(part.Size, 3),
            });
        }
        return items;
    }
}
