using AcShadow.Core.Catalog;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Forge.Scale;

/// <summary>
/// A realistic-scale spec for benchmarks, generated from a seed (same seed and counts, same spec, same
/// bytes), shaped like a retail portal dat: by default 7,000 Setups and 40,000 GfxObjs. Doors (3 parts:
/// leaf + two shared jambs, every door-setups.tsv id among them); statics of 1-30 parts (few parts
/// common, many rare) drawn from a shared physics pool whose polygon counts are long-tailed from 4 to
/// 2,000 (half the parts are 6-polygon boxes, about one in ten has 200 or more, a few percent have 1,000
/// or more: buildings built as clusters of rooms, subdivided walls, prisms); creatures of 2-30
/// drawing-only parts with CylSpheres only; items with Spheres only; GfxObjs no Setup uses (placed bare
/// by landblocks, or not at all); and landblocks placing them. Spec generation is sequential from one
/// <see cref="Random"/>; the costly part, building the PhysicsBSPs, runs in parallel in
/// <see cref="SpecCompiler"/> and is deterministic per GfxObj.
/// </summary>
public static class ScaleSpecGenerator
{
    public const int DefaultSetups = 7000;
    public const int DefaultGfxObjs = 40000;
    public const int DefaultSeed = 1;
    public const int MaxSetups = 50000;
    public const int MaxGfxObjs = 400000;
    public const int MaxParts = 30;
    public const int MinPhysicsPolygons = 4, MaxPhysicsPolygons = 2000;

    /// <summary>Objects the first landblock (0x0000FFFE) places: a busy landblock, for benchmarking scene compiles.</summary>
    public const int BusyLandblockObjects = 60;

    /// <summary>The GfxObj count <see cref="Generate"/> uses when none is given: the default dat's ratio.</summary>
    public static int GfxObjsFor(int setups) => (int)Math.Min(MaxGfxObjs, Math.Max(MinGfxObjs(setups), (long)setups * DefaultGfxObjs / DefaultSetups));

    /// <summary>The fewest GfxObjs a dat of this many Setups can have: jambs, a leaf per door, one of each pool.</summary>
    public static int MinGfxObjs(int setups) => DoorSetups.JambVariants + DoorSetups.Count(setups) + 4;

    public static ForgeSpec Generate(int setups = DefaultSetups, int seed = DefaultSeed, int? gfxObjCount = null)
    {
        if (setups < 1 || setups > MaxSetups) throw new ArgumentOutOfRangeException(nameof(setups), setups, $"setups must be 1-{MaxSetups}");
        var totalGfx = gfxObjCount ?? GfxObjsFor(setups);
        if (totalGfx < MinGfxObjs(setups) || totalGfx > MaxGfxObjs)
            throw new ArgumentOutOfRangeException(nameof(gfxObjCount), totalGfx, $"gfxObjs must be {MinGfxObjs(setups)}-{MaxGfxObjs} for {setups} Setups");
        var random = new Random(seed);
        var ids = new ScaleIds(DoorCatalog.SetupIds);
        var gfxObjs = new List<GfxObjSpec>(totalGfx);

        var doorCount = DoorSetups.Count(setups);
        var rest = setups - doorCount;
        var staticCount = rest * 45 / 100;
        var creatureCount = rest * 35 / 100;
        var itemCount = rest - staticCount - creatureCount;

        // The order below is the order of draws from the one Random: changing it changes every byte.
        var doors = DoorSetups.Generate(random, ids, doorCount, gfxObjs);
        var pools = PartPools.Generate(random, ids, totalGfx - gfxObjs.Count, gfxObjs);
        var statics = StaticSetups.Generate(random, ids, pools, staticCount);
        var creatures = CreatureSetups.Generate(random, ids, pools, creatureCount);
        var items = ItemSetups.Generate(random, ids, pools, itemCount);
        List<SetupSpec> setupSpecs = [.. doors, .. statics, .. creatures, .. items];
        var placeable = setupSpecs.Select(s => s.Id!).ToArray();
        var outdoors = OutdoorLandblocks.Generate(random, setups, placeable, pools.BareModels);

        var (motionTables, animations) = ScaleMotions.Assign(doors, statics, creatures, seed);
        var (environments, landblocks) = Interiors.Furnish(outdoors, placeable, seed);

        return new ForgeSpec
        {
            Iteration = 1,
            Provenance = $"forge scale --setups {setups} --gfxobjs {totalGfx} --seed {seed}: synthetic geometry; door Setup ids from the ACE world database door list",
            GfxObjs = gfxObjs,
            Setups = setupSpecs,
            MotionTables = motionTables,
            Animations = animations,
            Landblocks = landblocks,
            Environments = environments,
        };
    }
}
