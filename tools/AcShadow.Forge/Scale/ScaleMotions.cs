using AcShadow.Core.Catalog;
using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The scale spec's motion: every door is posed by a motion table (a catalog door by its catalog table,
/// the rest by a shared door table named as their DefaultMotionTable), half the creatures get one of a
/// few dozen creature tables, and one static in ten an animation (a DefaultAnimation, or one in twenty a
/// table of its own kind). Tables and animations are shared across Setups as in a retail dat. Drawn from
/// a Random of its own, so adding motion does not change the geometry the seed gives.
/// The pose rules of issue 27 each get a table of their own, with fixed ids, and draw nothing from the Random:
/// catalog door table <see cref="StyleDoorTable"/> starts in HandCombat (the NonCombat style command matters);
/// the first static gets <see cref="ThreeAnimationTable"/> (a default cycle of three animations), the second
/// <see cref="AbsentAnimationTable"/> (its cycle's last animation is not in the dat), and the first other static
/// of two or more parts <see cref="ShortAnimationTable"/> (part frames for part 0 only).
/// </summary>
internal static class ScaleMotions
{
    private const uint NonCombat = 0x8000003D, HandCombat = 0x8000003C, Ready = 0x41000003, On = 0x4000000B, Off = 0x4000000C;
    private const int CreatureTables = 40, StaticAnimations = 60, StaticTables = 20, MaxParts = ScaleSpecGenerator.MaxParts;
    public const uint StyleDoorTable = 0x0900002C, ThreeAnimationTable = 0x09000F01, AbsentAnimationTable = 0x09000F02, ShortAnimationTable = 0x09000F03;
    /// <summary>The rule tables' animations: 0x03000F01-0x03000F03 the three-animation cycle, 0x03000F04-0x03000F05 (and the absent 0x03000F06) the absent case, 0x03000F07 the short one.</summary>
    public const uint FirstRuleAnimation = 0x03000F01;

    public static (List<MotionTableSpec> Tables, List<AnimationSpec> Animations) Assign(
        IReadOnlyList<SetupSpec> doors, IReadOnlyList<SetupSpec> statics, IReadOnlyList<SetupSpec> creatures, int seed)
    {
        var random = new Random(seed ^ 0x5EED15);
        var tables = new List<MotionTableSpec>();
        var animations = new List<AnimationSpec>();
        var nextAnim = 0x03000100u;
        var nextTable = 0x09001000u;
        string NewAnim(int parts, int frames, Func<int, int, FrameSpec> frame)
        {
            var id = Hex(nextAnim++);
            animations.Add(new AnimationSpec
            {
                Id = id,
                Parts = parts,
                Frames = Enumerable.Range(0, frames).Select(f => (IReadOnlyList<FrameSpec>?)Enumerable.Range(0, parts).Select(p => frame(f, p)).ToArray()).ToArray(),
            });
            return id;
        }
        MotionTableSpec Table(string id, uint substate, IEnumerable<(uint Motion, string Anim)> cycles) => new()
        {
            Id = id,
            DefaultStyle = Hex(NonCombat),
            StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(substate) }],
            Cycles = cycles.Select(c => new MotionSpec { Style = Hex(NonCombat), Motion = Hex(c.Motion), Anims = [new AnimDataSpec { Anim = c.Anim }] }).ToArray(),
        };

        // Doors: closed = the door's Resting frames, open = its Default frames, from the first door using the table.
        var doorTables = new Dictionary<string, SetupSpec>();
        var sharedDoorTable = Hex(nextTable++);
        foreach (var door in doors)
        {
            var catalog = DoorCatalog.Find(Parse(door.Id!))?.MotionTables.FirstOrDefault();
            var table = catalog is { } c ? Hex(c) : sharedDoorTable;
            if (catalog is null) door.DefaultMotionTable = sharedDoorTable;
            doorTables.TryAdd(table, door);
        }
        foreach (var (table, door) in doorTables.OrderBy(p => p.Key, StringComparer.Ordinal))
        {
            var closed = door.Placements["Resting"]!;
            var open = door.Placements["Default"]!;
            var doorTable = Table(table, Off, [(Off, NewAnim(closed.Count, 1, (_, p) => closed[p])), (On, NewAnim(open.Count, 1, (_, p) => open[p]))]);
            // Starts in HandCombat Ready, standing open: only the NonCombat style command before Off closes it.
            if (table == Hex(StyleDoorTable))
                doorTable = doorTable with
                {
                    DefaultStyle = Hex(HandCombat),
                    StyleDefaults = [new StyleDefaultSpec { Style = Hex(HandCombat), Substate = Hex(Ready) }, .. doorTable.StyleDefaults],
                    Cycles = [new MotionSpec { Style = Hex(HandCombat), Motion = Hex(Ready), Anims = doorTable.Cycles[1].Anims }, .. doorTable.Cycles],
                };
            tables.Add(doorTable);
        }

        // Creatures: a Ready cycle of 10 frames posing up to 30 parts (a table serves creatures of any part count).
        var creatureTables = Enumerable.Range(0, CreatureTables)
            .Select(_ => Table(Hex(nextTable++), Ready, [(Ready, NewAnim(MaxParts, 10, (f, p) => At(0, 0.01 * f, 0.1 * p)))])).ToArray();
        tables.AddRange(creatureTables);
        foreach (var creature in creatures)
            if (random.Next(2) == 0) creature.DefaultMotionTable = creatureTables[random.Next(creatureTables.Length)].Id;

        // Statics: waving flags and turning wheels, a few centimetres off their placement.
        var staticAnims = Enumerable.Range(0, StaticAnimations).Select(_ => NewAnim(MaxParts, 5, (f, p) => At(0.02 * (f + 1), 0, 0.1 * p))).ToArray();
        var staticTables = Enumerable.Range(0, StaticTables).Select(i => Table(Hex(nextTable++), Ready, [(Ready, staticAnims[i])])).ToArray();
        tables.AddRange(staticTables);
        foreach (var item in statics)
            switch (random.Next(20))
            {
                case 0: item.DefaultMotionTable = staticTables[random.Next(staticTables.Length)].Id; break;
                case 1: item.DefaultAnimation = staticAnims[random.Next(staticAnims.Length)]; break;
            }
        AddRuleTables(statics, tables, animations);
        return (tables, animations);
    }

    /// <summary>Part p of every frame at (x, y, 0.1 p): each rule animation's frames are told apart by x and y alone.</summary>
    private static AnimationSpec RuleAnimation(uint id, int parts, params (double X, double Y)[] frames) => new()
    {
        Id = Hex(id),
        Parts = parts,
        Frames = frames.Select(f => (IReadOnlyList<FrameSpec>?)Enumerable.Range(0, parts).Select(p => At(f.X, f.Y, 0.1 * p)).ToArray()).ToArray(),
    };

    private static void AddRuleTables(IReadOnlyList<SetupSpec> statics, List<MotionTableSpec> tables, List<AnimationSpec> animations)
    {
        var shortStatic = statics.Skip(2).FirstOrDefault(s => s.Parts.Count >= 2);
        if (statics.Count < 2 || shortStatic is null) return;
        var a = FirstRuleAnimation;
        animations.AddRange(
        [
            RuleAnimation(a, MaxParts, (0.1, 0), (0.2, 0)),
            RuleAnimation(a + 1, MaxParts, (0, 0.1), (0, 0.2)),
            RuleAnimation(a + 2, MaxParts, (0.3, 0.1), (0.3, 0.2), (0.3, 0.3)),
            RuleAnimation(a + 3, MaxParts, (0.4, 0)),
            RuleAnimation(a + 4, MaxParts, (0, 0.4), (0, 0.5)),
            RuleAnimation(a + 6, 1, (0.05, 0.05)),
        ]);
        MotionTableSpec RuleTable(uint id, IReadOnlyList<AnimDataSpec> anims, IReadOnlyList<string>? missing = null) => new()
        {
            Id = Hex(id),
            DefaultStyle = Hex(NonCombat),
            StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Ready) }],
            Cycles = [new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Ready), Anims = anims }],
            MissingAnimations = missing ?? [],
        };
        tables.AddRange(
        [
            RuleTable(ThreeAnimationTable, [new() { Anim = Hex(a) }, new() { Anim = Hex(a + 1) }, new() { Anim = Hex(a + 2), Framerate = -30 }]),
            RuleTable(AbsentAnimationTable, [new() { Anim = Hex(a + 3) }, new() { Anim = Hex(a + 4), LowFrame = 1 }, new() { Anim = Hex(a + 5) }], [Hex(a + 5)]),
            RuleTable(ShortAnimationTable, [new() { Anim = Hex(a + 6) }]),
        ]);
        (statics[0].DefaultMotionTable, statics[1].DefaultMotionTable, shortStatic.DefaultMotionTable) = (Hex(ThreeAnimationTable), Hex(AbsentAnimationTable), Hex(ShortAnimationTable));
    }

    private static FrameSpec At(double x, double y, double z) => new() { Origin = [x, y, z] };

    private static uint Parse(string hex) => Convert.ToUInt32(hex[2..], 16);
}
