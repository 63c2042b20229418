using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>The scale spec's creatures: 2-30 drawing-only parts stacked upright, collided with CylSpheres only (one or two).</summary>
internal static class CreatureSetups
{
    public static List<SetupSpec> Generate(Random random, ScaleIds ids, PartPools pools, int count)
    {
        var creatures = new List<SetupSpec>(count);
        for (var c = 0; c < count; c++)
        {
            var parts = Enumerable.Range(0, PartCount(random, 2)).Select(_ => pools.NextDrawing()).ToArray();
            var radius = Range(random, 0.3, 1.2);
            var height = Range(random, 1.0, 3.0);
            var cyls = new List<CylSphereSpec> { new() { Origin = [0, 0, 0], Radius = radius, Height = height } };
            if (random.Next(3) == 0) cyls.Add(new CylSphereSpec { Origin = [0, radius / 2, height * 0.8], Radius = radius / 2, Height = height * 0.2 });
            creatures.Add(new SetupSpec
            {
                Id = Hex(ids.NewSetup()),
                Parts = parts.Select(p => Hex(p.Id)).ToArray(),
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?>
                {
                    ["Resting"] = parts.Select((p, i) => Frame(0, 0, height * i / parts.Length, 0)).ToArray(),
                },
                CylSpheres = cyls,
                Radius = radius,
                Height = height,
                StepUpHeight = Math.Round(height / 3, 3),
                StepDownHeight = Math.Round(height / 3, 3),
                Flags = ["AllowFreeHeading"],
            });
        }
        return creatures;
    }
}
