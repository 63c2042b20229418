using AcShadow.Core.Catalog;
using AcShadow.Forging.Geometry;
using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The scale spec's doors: three parts each (a leaf of its own and two jambs shared from a few variants,
/// one per doorway width), every door catalog Setup id among them, posed closed (Resting) and open (Default).
/// </summary>
internal static class DoorSetups
{
    public const int JambVariants = 16;

    /// <summary>One Setup in ten, and never fewer than the door catalog names (unless the dat is smaller).</summary>
    public static int Count(int setups) => Math.Min(setups, Math.Max(DoorCatalog.SetupIds.Count, setups / 10));

    /// <summary>Adds the jambs and every door's leaf to <paramref name="gfxObjs"/>; returns the door Setups.</summary>
    public static List<SetupSpec> Generate(Random random, ScaleIds ids, int count, List<GfxObjSpec> gfxObjs)
    {
        var jambs = Jambs(ids, gfxObjs);
        var doorIds = DoorCatalog.SetupIds;
        var doors = new List<SetupSpec>(count);
        for (var d = 0; d < count; d++)
        {
            var setupId = d < doorIds.Count ? doorIds[d] : ids.NewSetup();
            var (jamb, width) = jambs[random.Next(jambs.Count)];
            var half = width / 2 - 0.035f;
            var thick = (float)Range(random, 0.05, 0.3);
            var leafId = ids.NewGfxObj();
            var subdivide = random.Next(4) == 0 ? random.Next(2, 5) : 1;
            gfxObjs.Add(new MeshBuilder()
                .Box(new(-half, -thick / 2, 0), new(half, thick / 2, 2.2f), subdivide, 1, subdivide)
                .ToSpec(leafId, true, true));
            var hingeX = width / 2 - 0.035f;
            doors.Add(new SetupSpec
            {
                Id = Hex(setupId),
                Parts = [Hex(leafId), Hex(jamb), Hex(jamb)],
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?>
                {
                    ["Resting"] = [Frame(0, 0, 0, 0), Frame(width / 2, 0, 0, 0), Frame(-width / 2, 0, 0, 180)],
                    ["Default"] = [Frame(hingeX, -hingeX, 0, 90), Frame(width / 2, 0, 0, 0), Frame(-width / 2, 0, 0, 180)],
                },
                Spheres = [new SphereSpec { Center = [0, 0, 0.018], Radius = 0.1 }],
                Radius = 0.141,
                Height = 0.2,
                Flags = ["HasPhysicsBsp"],
            });
        }
        return doors;
    }

    /// <summary>A jamb post with a threshold quad reaching across its doorway, one variant per width.</summary>
    private static List<(uint Id, float Width)> Jambs(ScaleIds ids, List<GfxObjSpec> gfxObjs)
    {
        var jambs = new List<(uint Id, float Width)>(JambVariants);
        for (var v = 0; v < JambVariants; v++)
        {
            var width = 1.0f + 0.1f * v;
            var id = ids.NewGfxObj();
            gfxObjs.Add(new MeshBuilder()
                .Box(new(-0.05f, -0.15f, 0), new(0.05f, 0.15f, 2.4f + 0.05f * v))
                .Polygon([new(0, 0, 0), new(-width, 0, 0), new(-width, 0, 0.3f), new(0, 0, 0.3f)])
                .ToSpec(id, true, true));
            jambs.Add((id, width));
        }
        return jambs;
    }
}
