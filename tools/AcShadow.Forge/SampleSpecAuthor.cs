using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Geometry;
using AcShadow.Forging;
using AcShadow.Forging.Geometry;
using AcShadow.Forging.Spec;

namespace AcShadow.Forge;

/// <summary>
/// Writes the built-in sample spec in code (a 310-polygon house is not typed by hand). Its JSON,
/// Sample/sample.json, is what this assembly embeds and the CLI and forge build; `forge sample --write-spec FILE`
/// regenerates that file from here, and a test keeps the two identical.
/// </summary>
public static class SampleSpecAuthor
{
    public const uint DoorSetup = 0x020019FF, DoorLeaf = 0x010044B5, DoorJamb = 0x010044B6;
    public const uint SinglePartDoorSetup = 0x0200024F, SinglePartDoor = 0x01000A10;
    public const uint DoubleDoorSetup = 0x02000281, DoubleDoorLeaf = 0x01000B20, DoubleDoorLintel = 0x01000B21, DoubleDoorFrame = 0x01000B22;
    public const uint CreatureSetup = 0x02001000, CreatureTorso = 0x01001000, CreatureHead = 0x01001001, CreatureLeg = 0x01001002;
    /// <summary>The person-sized two-sphere mover `acshadow move` walks on the sample (synthetic: holtburger's human values).</summary>
    public const uint MoverSetup = SampleDats.MoverSetup;
    public const uint ItemSetup = 0x02002000, ItemGem = 0x01002000;
    public const uint StaticSetup = 0x02003000, Pedestal = 0x01003000, LBlock = 0x01003001, Column = 0x01003002;
    public const uint FlagWithoutBspSetup = 0x02003100, OtherOnlySetup = 0x02003200, NoPlacementSetup = 0x02003300;
    public const uint MissingPartSetup = 0x02003400, MissingPart = 0x0100DEAD;
    public const uint BuildingSetup = 0x02005000, House = 0x01005000;
    public const uint OddSetup = 0x02006000, OddGfxObj = 0x01006000;
    public const uint Landblock = 0xA9B4FFFE;
    public const uint CottageEnvironment = 0x0D000100, GroundFloorCell = 0xA9B40100, CellarCell = 0xA9B40101;
    /// <summary>Where both cottage cells sit in the landblock: one origin, turned 90° about Z.</summary>
    public static readonly Vector3 CottageOrigin = new(60, 60, 12);

    // Motion: door tables use the ids the door catalog names for these door Setups.
    public const uint DoorMotionTable = 0x09000202, DoorClosedAnim = 0x03000100, DoorOpenAnim = 0x03000101, DoorSwingAnim = 0x03000102;
    public const uint NoDefaultCycleTable = 0x09000016, NoDefaultCycleOpenAnim = 0x03000016;
    public const uint AnimatedStaticSetup = 0x02003500, AnimatedStaticTable = 0x09003500, AnimatedStaticAnim = 0x03003500;
    public const uint DefaultAnimationSetup = 0x02003600, DefaultAnimationAnim = 0x03003600;
    // The pose rules of issue 27, one Setup each: a default cycle of three animations, a door whose table starts
    // in another style (0x02000311 is a catalog door; its catalog table is 0x0900002C), a cycle naming an animation
    // the dat lacks, and a DefaultAnimation with part frames for 2 of its Setup's 3 parts.
    public const uint ThreeAnimationSetup = 0x02003700, ThreeAnimationTable = 0x09003700, CycleFirstAnim = 0x03003701, CycleSecondAnim = 0x03003702, CycleLastAnim = 0x03003703;
    public const uint StyleDoorSetup = 0x02000311, StyleDoorTable = 0x0900002C;
    public const uint StyleDoorCombatAnim = 0x0300002C, StyleDoorClosedAnim = 0x0300002D, StyleDoorOpenAnim = 0x0300002E, StyleDoorCombatOffAnim = 0x0300002F;
    public const uint AbsentAnimationSetup = 0x02003800, AbsentAnimationTable = 0x09003800, AbsentCaseFirstAnim = 0x03003801, AbsentCaseSecondAnim = 0x03003802, AbsentAnim = 0x03003803;
    public const uint ShortAnimationSetup = 0x02003900, ShortAnimationAnim = 0x03003900;
    public const uint NonCombat = 0x8000003D, HandCombat = 0x8000003C, Ready = 0x41000003, On = 0x4000000B, Off = 0x4000000C;

    public static ForgeSpec Create() => new()
    {
        Iteration = 1,
        Provenance = "Setup ids 0x020019FF, 0x0200024F, 0x02000281 and 0x02000311 are door Setups from the public ACE world database "
            + "door list (door-setups.tsv); 0x020019FF's part ids, Sphere, Radius and Height follow published retail facts. "
            + "All geometry is synthetic (invented, part-local metres, Z up); every other id is invented.",
        Comment = "The forge's built-in sample: one object per collision case acshadow must handle. Regenerate with `forge sample --write-spec`.",
        GfxObjs =
        [
            new MeshBuilder().Box(new(-0.965f, -0.13f, 0f), new(0.965f, 0.13f, 2.2f))
                .ToSpec(DoorLeaf, true, true, "door leaf: closed box 1.93 x 0.26 x 2.2 m, 6 quads"),
            new MeshBuilder().Box(new(-0.05f, -0.15f, 0f), new(0.05f, 0.15f, 2.3f))
                .Polygon([new(0f, 0f, 0f), new(-2f, 0f, 0f), new(-2f, 0f, 0.3f), new(0f, 0f, 0.3f)])
                .ToSpec(DoorJamb, true, true, "door jamb post (closed box 0.1 x 0.3 x 2.3 m) plus a one-sided threshold quad in y=0 reaching 2 m across the doorway (-x), 0.3 m tall"),
            new MeshBuilder()
                .Box(new(-0.95f, -0.05f, 0f), new(0.95f, 0.05f, 2.1f))
                .Box(new(-1.1f, -0.15f, 0f), new(-0.95f, 0.15f, 2.3f))
                .Box(new(0.95f, -0.15f, 0f), new(1.1f, 0.15f, 2.3f))
                .Box(new(-0.95f, -0.15f, 2.1f), new(0.95f, 0.15f, 2.3f))
                .Polygon([new(-0.95f, 0f, 0f), new(0.95f, 0f, 0f), new(0.95f, 0f, 0.25f), new(-0.95f, 0f, 0.25f)])
                .ToSpec(SinglePartDoor, true, true, "single-part door: leaf, two posts, lintel and threshold in one GfxObj"),
            new MeshBuilder().Box(new(0f, -0.05f, 0f), new(0.95f, 0.05f, 2.4f))
                .ToSpec(DoubleDoorLeaf, true, true, "double-door leaf, hinge edge at local x=0, 0.95 m wide"),
            new MeshBuilder().Box(new(-1.1f, -0.15f, 2.4f), new(1.1f, 0.15f, 2.7f))
                .ToSpec(DoubleDoorLintel, true, true, "double-door lintel"),
            new MeshBuilder()
                .Box(new(-1.1f, -0.15f, 0f), new(-0.95f, 0.15f, 2.4f))
                .Box(new(0.95f, -0.15f, 0f), new(1.1f, 0.15f, 2.4f))
                .Polygon([new(-0.95f, 0f, 0f), new(0.95f, 0f, 0f), new(0.95f, 0f, 0.2f), new(-0.95f, 0f, 0.2f)], "None")
                .ToSpec(DoubleDoorFrame, true, true, "double-door frame: two posts and a two-sided (sidesType None) threshold across the 1.9 m opening"),
            new MeshBuilder().Box(new(-0.25f, -0.15f, 0.9f), new(0.25f, 0.15f, 1.45f))
                .ToSpec(CreatureTorso, false, true, "creature torso, drawing only"),
            new MeshBuilder().Prism(new(0f, 0f, 0f), 0.12f, 0.3f, 8)
                .ToSpec(CreatureHead, false, true, "creature head, drawing only"),
            new MeshBuilder().Box(new(-0.08f, -0.08f, 0f), new(0.08f, 0.08f, 0.9f))
                .ToSpec(CreatureLeg, false, true, "creature leg, drawing only (used twice)"),
            Gem().ToSpec(ItemGem, false, true, "item gem (octahedron), drawing only"),
            new MeshBuilder().Box(new(-0.5f, -0.5f, 0f), new(0.5f, 0.5f, 0.5f), 2, 2, 1)
                .ToSpec(Pedestal, true, true, "pedestal: closed box with 2x2-subdivided faces"),
            LShape().ToSpec(LBlock, true, true, "L-shaped closed, non-convex block (7 sides, top and bottom as two convex pieces each)"),
            new MeshBuilder().Prism(new(0f, 0f, 0f), 0.25f, 2f, 8, 2)
                .ToSpec(Column, true, true, "octagonal column, 2 rings; also placed bare in the landblock"),
            HouseMesh().ToSpec(House, true, true, "house 10 x 8 m: floor, two-sided subdivided walls with a door opening, interior wall, gable roof, furniture boxes (310 polygons)"),
            OddMesh().ToSpec(OddGfxObj, true, false, "closed box plus one degenerate (collinear) triangle (polygon 6) and one non-planar quad (polygon 7); physics only"),
        ],
        Setups =
        [
            new SetupSpec
            {
                Id = Hex(DoorSetup),
                Comment = "3-part door: leaf + two jambs, the second mirrored by 180 deg about Z so both thresholds span the doorway. "
                    + "Default (leaf open 90 deg about its hinge) differs from Resting (closed) and is listed first: retail asks for Resting. "
                    + "Its catalog motion table 0x09000202 closes it 5 cm along x from where Resting puts it, and opens it 90 deg.",
                Parts = [Hex(DoorLeaf), Hex(DoorJamb), Hex(DoorJamb)],
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?>
                {
                    ["Default"] = [At(0.965, -0.965, 0, Z(90)), At(1, 0, 0), At(-1, 0, 0, Z(180))],
                    ["Resting"] = [At(0, 0, 0), At(1, 0, 0), At(-1, 0, 0, Z(180))],
                },
                Spheres = [new SphereSpec { Center = [0, 0, 0.018], Radius = 0.1 }],
                Radius = 0.141,
                Height = 0.2,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(SinglePartDoorSetup),
                Comment = "single-part door: one GfxObj holds leaf and frame; Resting only. Its catalog motion table 0x09000016 lacks its default cycle",
                Parts = [Hex(SinglePartDoor)],
                Placements = Place(("Resting", [At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.02], Radius = 0.1 }],
                Radius = 0.141,
                Height = 0.2,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(DoubleDoorSetup),
                Comment = "double door, 4 parts: two leaves (one GfxObj, mirrored), lintel, frame; Default swings both leaves open. Catalog motion table 0x09000016 (no default cycle)",
                Parts = [Hex(DoubleDoorLeaf), Hex(DoubleDoorLeaf), Hex(DoubleDoorLintel), Hex(DoubleDoorFrame)],
                Placements = Place(
                    ("Resting", [At(-0.95, 0, 0), At(0.95, 0, 0, Z(180)), At(0, 0, 0), At(0, 0, 0)]),
                    ("Default", [At(-0.95, 0, 0, Z(-90)), At(0.95, 0, 0, Z(-90)), At(0, 0, 0), At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.02], Radius = 0.12 }],
                Radius = 0.17,
                Height = 0.24,
                Flags = ["HasPhysicsBsp"],
                // Every hook type the public readers define, so the placement frames are read as real ones are.
                Hooks = new Dictionary<string, IReadOnlyList<HookSpec>?> { ["Default"] = OpeningHooks(), ["Resting"] = ClosingHooks() },
            },
            new SetupSpec
            {
                Id = Hex(CreatureSetup),
                Comment = "creature: two CylSpheres, drawing-only parts (no BSP anywhere)",
                Parts = [Hex(CreatureTorso), Hex(CreatureHead), Hex(CreatureLeg), Hex(CreatureLeg)],
                Placements = Place(("Resting", [At(0, 0, 0), At(0, 0, 1.45), At(-0.12, 0, 0), At(0.12, 0, 0)])),
                CylSpheres =
                [
                    new CylSphereSpec { Origin = [0, 0, 0], Radius = 0.35, Height = 1.8 },
                    new CylSphereSpec { Origin = [0, 0.1, 1.45], Radius = 0.2, Height = 0.35 },
                ],
                Radius = 0.35,
                Height = 1.8,
                StepUpHeight = 0.6,
                StepDownHeight = 0.6,
                Flags = ["AllowFreeHeading"],
            },
            new SetupSpec
            {
                Id = Hex(MoverSetup),
                Comment = "mover: a person-sized walker for `move` (SYNTHETIC, not read from a retail dat): foot sphere (0,0,0.475) and head sphere (0,0,1.35), r 0.48, "
                    + "step up 0.6 m, step down 1.5 m (holtburger's human values); the creature torso as its drawing-only part",
                Parts = [Hex(CreatureTorso)],
                Placements = Place(("Resting", [At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.475], Radius = 0.48 }, new SphereSpec { Center = [0, 0, 1.35], Radius = 0.48 }],
                Radius = 0.48,
                Height = 1.83,
                StepUpHeight = 0.6,
                StepDownHeight = 1.5,
            },
            new SetupSpec
            {
                Id = Hex(ItemSetup),
                Comment = "item: Spheres only, one drawing-only part",
                Parts = [Hex(ItemGem)],
                Placements = Place(("Default", [At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.08], Radius = 0.1 }],
                Radius = 0.1,
                Height = 0.16,
            },
            new SetupSpec
            {
                Id = Hex(StaticSetup),
                Comment = "multi-part static: 3 physics parts, rotated (about Z and about X), non-uniform DefaultScale; "
                    + "flag HasPhysicsBsp NOT set although every part has a BSP",
                Parts = [Hex(Pedestal), Hex(LBlock), Hex(Column)],
                Placements = Place(("Resting", [At(0, 0, 0), At(-0.3, -0.3, 0.75, Z(45)), At(0.6, 0.2, 1.0, X(90))])),
                DefaultScale = [[1, 1, 1.5], [0.8, 1.2, 1.5], [1, 1, 0.5]],
                Radius = 1.2,
                Height = 1.6,
            },
            new SetupSpec
            {
                Id = Hex(FlagWithoutBspSetup),
                Comment = "flag HasPhysicsBsp set, but its only part is drawing-only (no part has a BSP); has a Sphere",
                Parts = [Hex(ItemGem)],
                Placements = Place(("Default", [At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.08], Radius = 0.1 }],
                Radius = 0.1,
                Height = 0.16,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(OtherOnlySetup),
                Comment = "only placement is Other (neither Resting nor Default): retail gives its parts no placement frame",
                Parts = [Hex(Pedestal), Hex(Column)],
                Placements = Place(("Other", [At(0, 0, 0), At(0, 0, 0.5, Z(30))])),
                Radius = 0.8,
                Height = 2.5,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(NoPlacementSetup),
                Comment = "single physics part, no placement frames at all: the part sits at the entity origin",
                Parts = [Hex(LBlock)],
                Radius = 0.8,
                Height = 0.6,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(MissingPartSetup),
                Comment = "part 0x0100DEAD is deliberately absent from the dat",
                Parts = [Hex(Pedestal), Hex(MissingPart)],
                Placements = Place(("Resting", [At(0, 0, 0), At(0, 0, 0.5)])),
                Radius = 0.8,
                Height = 1,
                Flags = ["HasPhysicsBsp"],
                MissingParts = [Hex(MissingPart)],
            },
            new SetupSpec
            {
                Id = Hex(AnimatedStaticSetup),
                Comment = "animated static: a motion table whose default cycle's animation has part frames for 1 of its 2 parts (the pedestal, raised 0.25 m); "
                    + "it also names a DefaultAnimation, which the motion table's default state replaces",
                Parts = [Hex(Pedestal), Hex(Column)],
                Placements = Place(("Resting", [At(0, 0, 0), At(0, 0, 0.5)])),
                DefaultAnimation = Hex(DefaultAnimationAnim),
                DefaultMotionTable = Hex(AnimatedStaticTable),
                Radius = 0.8,
                Height = 2.5,
                Flags = ["HasPhysicsBsp"],
            },
            ColumnSetup(DefaultAnimationSetup, "a DefaultAnimation and no motion table: its first frame moves the column 0.3 m along x from Resting") with
            {
                DefaultAnimation = Hex(DefaultAnimationAnim),
            },
            ColumnSetup(ThreeAnimationSetup, "a default cycle of three animations: once in the world only the last (played backwards, from its last frame) is left; "
                + "the first would put the column 0.1 m along x") with
            {
                DefaultMotionTable = Hex(ThreeAnimationTable),
            },
            new SetupSpec
            {
                Id = Hex(StyleDoorSetup),
                Comment = "single-part door whose catalog motion table 0x0900002C starts in HandCombat: the NonCombat style command comes before Off or On, "
                    + "so the door closes by NonCombat's Off cycle, not HandCombat's",
                Parts = [Hex(SinglePartDoor)],
                Placements = Place(("Resting", [At(0, 0, 0)])),
                Spheres = [new SphereSpec { Center = [0, 0, 0.02], Radius = 0.1 }],
                Radius = 0.141,
                Height = 0.2,
                Flags = ["HasPhysicsBsp"],
            },
            ColumnSetup(AbsentAnimationSetup, "a default cycle of three animations whose last is absent from the dat: retail drops it, so the second is left current") with
            {
                DefaultMotionTable = Hex(AbsentAnimationTable),
            },
            new SetupSpec
            {
                Id = Hex(ShortAnimationSetup),
                Comment = "3 parts and a DefaultAnimation with part frames for the first 2: retail never places the column, which keeps the frame it was made with",
                Parts = [Hex(Pedestal), Hex(LBlock), Hex(Column)],
                Placements = Place(("Resting", [At(0, 0, 0), At(-0.3, -0.3, 0.75, Z(45)), At(0.6, 0.2, 1.0, X(90))])),
                DefaultAnimation = Hex(ShortAnimationAnim),
                Radius = 1.2,
                Height = 2,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(BuildingSetup),
                Comment = "building Setup around the house GfxObj (the landblock also places the GfxObj bare, as a building)",
                Parts = [Hex(House)],
                Placements = Place(("Default", [At(0, 0, 0)])),
                Radius = 7.2,
                Height = 5,
                Flags = ["HasPhysicsBsp"],
            },
            new SetupSpec
            {
                Id = Hex(OddSetup),
                Comment = "holds the GfxObj with a degenerate and a non-planar polygon",
                Parts = [Hex(OddGfxObj)],
                Placements = Place(("Resting", [At(0, 0, 0)])),
                Radius = 2,
                Height = 3.2,
                Flags = ["HasPhysicsBsp"],
            },
        ],
        MotionTables =
        [
            new MotionTableSpec
            {
                Id = Hex(DoorMotionTable),
                Comment = "door: NonCombat starts Off (closed); On is open; links swing the leaf between them",
                DefaultStyle = Hex(NonCombat),
                StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Off) }],
                Cycles =
                [
                    new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Off), Anims = [Anim(DoorClosedAnim)] },
                    new MotionSpec { Style = Hex(NonCombat), Motion = Hex(On), Anims = [Anim(DoorOpenAnim)] },
                ],
                Links =
                [
                    new LinkSpec { Style = Hex(NonCombat), From = Hex(Off), To = Hex(On), Anims = [Anim(DoorSwingAnim)] },
                    new LinkSpec { Style = Hex(NonCombat), From = Hex(On), To = Hex(Off), Anims = [Anim(DoorSwingAnim, -30)] },
                ],
            },
            new MotionTableSpec
            {
                Id = Hex(NoDefaultCycleTable),
                Comment = "broken door table: NonCombat's default substate is Off, but there is no Off cycle (only On): the default state fails",
                DefaultStyle = Hex(NonCombat),
                StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Off) }],
                Cycles = [new MotionSpec { Style = Hex(NonCombat), Motion = Hex(On), Anims = [Anim(NoDefaultCycleOpenAnim)] }],
            },
            new MotionTableSpec
            {
                Id = Hex(AnimatedStaticTable),
                Comment = "animated static: NonCombat Ready plays an animation that poses only part 0",
                DefaultStyle = Hex(NonCombat),
                StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Ready) }],
                Cycles = [new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Ready), Anims = [Anim(AnimatedStaticAnim)], Omega = [0, 0, 0.5] }],
            },
            new MotionTableSpec
            {
                Id = Hex(ThreeAnimationTable),
                Comment = "NonCombat Ready plays three animations; the last, backwards, is the cyclic one",
                DefaultStyle = Hex(NonCombat),
                StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Ready) }],
                Cycles = [new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Ready), Anims = [Anim(CycleFirstAnim), Anim(CycleSecondAnim), Anim(CycleLastAnim, -30)] }],
            },
            new MotionTableSpec
            {
                Id = Hex(StyleDoorTable),
                Comment = "door table starting in HandCombat Ready; NonCombat's default is Off; HandCombat has an Off cycle of its own (what skipping the style command would play) "
                    + "and a link to NonCombat",
                DefaultStyle = Hex(HandCombat),
                StyleDefaults =
                [
                    new StyleDefaultSpec { Style = Hex(HandCombat), Substate = Hex(Ready) },
                    new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Off) },
                ],
                Cycles =
                [
                    new MotionSpec { Style = Hex(HandCombat), Motion = Hex(Ready), Anims = [Anim(StyleDoorCombatAnim)] },
                    new MotionSpec { Style = Hex(HandCombat), Motion = Hex(Off), Anims = [Anim(StyleDoorCombatOffAnim)] },
                    new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Off), Anims = [Anim(StyleDoorClosedAnim)] },
                    new MotionSpec { Style = Hex(NonCombat), Motion = Hex(On), Anims = [Anim(StyleDoorOpenAnim)] },
                ],
                Links = [new LinkSpec { Style = Hex(HandCombat), From = Hex(Ready), To = Hex(NonCombat), Anims = [Anim(StyleDoorCombatOffAnim)] }],
            },
            new MotionTableSpec
            {
                Id = Hex(AbsentAnimationTable),
                Comment = "NonCombat Ready plays three animations, the last of them left out of the dat",
                DefaultStyle = Hex(NonCombat),
                StyleDefaults = [new StyleDefaultSpec { Style = Hex(NonCombat), Substate = Hex(Ready) }],
                Cycles = [new MotionSpec { Style = Hex(NonCombat), Motion = Hex(Ready), Anims = [Anim(AbsentCaseFirstAnim), Anim(AbsentCaseSecondAnim, lowFrame: 1), Anim(AbsentAnim)] }],
                MissingAnimations = [Hex(AbsentAnim)],
            },
        ],
        Animations =
        [
            new AnimationSpec
            {
                Id = Hex(DoorClosedAnim),
                Comment = "door closed: leaf 5 cm towards the first jamb from where Resting puts it, jambs as Resting",
                Parts = 3,
                Frames = [[At(0.05, 0, 0), At(1, 0, 0), At(-1, 0, 0, Z(180))]],
            },
            new AnimationSpec
            {
                Id = Hex(DoorOpenAnim),
                Comment = "door open: leaf turned 90 deg about Z around its hinge edge (local x = 0.965)",
                Parts = 3,
                Frames = [[At(0.965, -0.965, 0, Z(90)), At(1, 0, 0), At(-1, 0, 0, Z(180))]],
            },
            new AnimationSpec
            {
                Id = Hex(DoorSwingAnim),
                Comment = "door swing, closed to open in three frames (0, 45, 90 deg)",
                Parts = 3,
                Frames =
                [
                    [At(0.05, 0, 0), At(1, 0, 0), At(-1, 0, 0, Z(180))],
                    [At(0.283, -0.683, 0, Z(45)), At(1, 0, 0), At(-1, 0, 0, Z(180))],
                    [At(0.965, -0.965, 0, Z(90)), At(1, 0, 0), At(-1, 0, 0, Z(180))],
                ],
            },
            new AnimationSpec
            {
                Id = Hex(NoDefaultCycleOpenAnim),
                Comment = "the broken table's only animation: never reached",
                Parts = 1,
                Frames = [[At(0, 0, 0)]],
            },
            new AnimationSpec
            {
                Id = Hex(AnimatedStaticAnim),
                Comment = "one part frame per frame for a 2-part Setup: frame 0 raises the pedestal 0.25 m, frame 1 0.5 m",
                Parts = 1,
                Frames = [[At(0, 0, 0.25)], [At(0, 0, 0.5)]],
                PosFrames = [At(0, 0, 0), At(0.1, 0, 0)],
            },
            new AnimationSpec
            {
                Id = Hex(DefaultAnimationAnim),
                Comment = "two frames: the column 0.3 m along x, then 0.6 m",
                Parts = 1,
                Frames = [[At(0.3, 0, 0)], [At(0.6, 0, 0)]],
            },
            OnePartAnimation(CycleFirstAnim, "first of three: the column 0.1 m along x, then 0.2 m", At(0.1, 0, 0), At(0.2, 0, 0)),
            OnePartAnimation(CycleSecondAnim, "second of three: the column 0.1 m along y, then 0.2 m", At(0, 0.1, 0), At(0, 0.2, 0)),
            OnePartAnimation(CycleLastAnim, "last of three: the column 0.1, 0.2, then 0.3 m up, the last frame also turned 90 deg about Z", At(0, 0, 0.1), At(0, 0, 0.2), At(0, 0, 0.3, Z(90))),
            OnePartAnimation(StyleDoorCombatAnim, "the style door in HandCombat Ready: lifted 0.4 m", At(0, 0, 0.4)),
            OnePartAnimation(StyleDoorClosedAnim, "the style door closed (NonCombat Off): 2 cm along x", At(0.02, 0, 0)),
            OnePartAnimation(StyleDoorOpenAnim, "the style door open (NonCombat On): turned 90 deg about Z, 0.5 m along -y", At(0, -0.5, 0, Z(90))),
            OnePartAnimation(StyleDoorCombatOffAnim, "HandCombat Off, and the link from HandCombat Ready to NonCombat: sunk 1 m", At(0, 0, -1)),
            OnePartAnimation(AbsentCaseFirstAnim, "first of the cycle with an absent animation: the column 0.5 m along x", At(0.5, 0, 0)),
            OnePartAnimation(AbsentCaseSecondAnim, "second of the cycle with an absent animation (played from frame 1): the column 0.5, then 0.7 m along y", At(0, 0.5, 0), At(0, 0.7, 0)),
            new AnimationSpec
            {
                Id = Hex(ShortAnimationAnim),
                Comment = "part frames for 2 of 3 parts: the pedestal 0.2 m up, the L-block 0.2 m above its Resting frame",
                Parts = 2,
                Frames = [[At(0, 0, 0.2), At(-0.3, -0.3, 0.95, Z(45))]],
            },
        ],
        Landblocks =
        [
            new LandblockSpec
            {
                Id = Hex(Landblock),
                Comment = "one landblock: the door standing in the house's opening, a bare GfxObj, the multi-part static (Stabs) and the house (a BuildingInfo), all turned about Z",
                Objects =
                [
                    // In the house's front-wall opening: the house (turned 90 deg) puts its local (0, -4) at (136, 108).
                    new StabSpec { Id = Hex(DoorSetup), Origin = [136, 108, 12], Orientation = Z(90) },
                    new StabSpec { Id = Hex(Column), Origin = [30, 150, 10], Orientation = Z(120) },
                    new StabSpec { Id = Hex(StaticSetup), Origin = [100, 30, 11], Orientation = Z(-45) },
                ],
                Buildings = [new BuildingSpec { ModelId = Hex(House), Origin = [132, 108, 12], Orientation = Z(90), NumLeaves = 4 }],
                Cells =
                [
                    new CellSpec
                    {
                        Comment = "cottage ground floor: door to the outside in its front wall (portal 0), stairwell down to the cellar (portal 1), the L-block Setup inside",
                        Environment = Hex(CottageEnvironment),
                        CellStruct = 0,
                        Origin = [CottageOrigin.X, CottageOrigin.Y, CottageOrigin.Z],
                        Orientation = Z(90),
                        SeenOutside = true,
                        Portals =
                        [
                            new CellPortalSpec { Polygon = 0, OtherCell = "outside", Flags = "PortalSide" },
                            new CellPortalSpec { Polygon = 1, OtherCell = "0x0101", OtherPortal = 0, Flags = "ExactMatch" },
                        ],
                        VisibleCells = ["0x0101"],
                        // Cell-local (-2.5, -2, 0), turned with the cell: landblock (60 + 2, 60 - 2.5, 12).
                        Objects = [new StabSpec { Id = Hex(NoPlacementSetup), Origin = [62, 57.5, 12], Orientation = Z(90) }],
                    },
                    new CellSpec
                    {
                        Comment = "cottage cellar, 3 m below, reached by the ramp under the stairwell (portal 0 up to the ground floor)",
                        Environment = Hex(CottageEnvironment),
                        CellStruct = 1,
                        Origin = [CottageOrigin.X, CottageOrigin.Y, CottageOrigin.Z],
                        Orientation = Z(90),
                        Portals = [new CellPortalSpec { Polygon = 0, OtherCell = "0x0100", OtherPortal = 1, Flags = "ExactMatch" }],
                        VisibleCells = ["0x0100"],
                    },
                ],
            },
        ],
        Environments =
        [
            new EnvironmentSpec
            {
                Id = Hex(CottageEnvironment),
                Comment = "a cottage's two cell shapes, in one cell-local frame (x across, y deep, z up; the front wall at y = -2.5)",
                CellStructs = [GroundFloor(), Cellar()],
            },
        ],
    };

    /// <summary>
    /// The ground floor, 6 x 5 m (x in [-3, 3], y in [-2.5, 2.5]): walls face into the room; the front
    /// wall (y = -2.5, 3 m tall) has a 2 x 2.2 m door; the ceiling is one tilted polygon rising from 3 m at
    /// the front to 3.5 m at the back; the floor leaves a 4 x 1.5 m stairwell (x in [-1, 3], y in [1, 2.5]).
    /// Portals: the door, then the stairwell.
    /// </summary>
    private static CellStructSpec GroundFloor()
    {
        var m = new MeshBuilder();
        m.Polygon([new(-3, -2.5f, 0), new(3, -2.5f, 0), new(3, 1, 0), new(-3, 1, 0)]);                 // floor before the stairwell
        m.Polygon([new(-3, 1, 0), new(-1, 1, 0), new(-1, 2.5f, 0), new(-3, 2.5f, 0)]);                  // floor beside it
        m.Polygon([new(-3, 2.5f, 0), new(3, 2.5f, 0), new(3, 2.5f, 3.5f), new(-3, 2.5f, 3.5f)]);         // back wall
        m.Polygon([new(3, -2.5f, 0), new(3, -2.5f, 3), new(3, 2.5f, 3.5f), new(3, 2.5f, 0)]);            // right wall
        m.Polygon([new(-3, -2.5f, 0), new(-3, 2.5f, 0), new(-3, 2.5f, 3.5f), new(-3, -2.5f, 3)]);        // left wall
        m.Polygon([new(-3, -2.5f, 0), new(-3, -2.5f, 3), new(-1, -2.5f, 3), new(-1, -2.5f, 0)]);         // front wall, left of the door
        m.Polygon([new(1, -2.5f, 0), new(1, -2.5f, 3), new(3, -2.5f, 3), new(3, -2.5f, 0)]);             // front wall, right of the door
        m.Polygon([new(-1, -2.5f, 2.2f), new(-1, -2.5f, 3), new(1, -2.5f, 3), new(1, -2.5f, 2.2f)]);     // above the door
        m.Polygon([new(-3, -2.5f, 3), new(-3, 2.5f, 3.5f), new(3, 2.5f, 3.5f), new(3, -2.5f, 3)]);       // tilted ceiling
        var walls = m.PolygonCount;
        m.Polygon([new(-1, -2.5f, 0), new(1, -2.5f, 0), new(1, -2.5f, 2.2f), new(-1, -2.5f, 2.2f)]);     // portal 0: the door
        m.Polygon([new(-1, 1, 0), new(3, 1, 0), new(3, 2.5f, 0), new(-1, 2.5f, 0)]);                     // portal 1: the stairwell
        return m.ToCellStructSpec(walls, "ground floor: 2 floor pieces, 3 walls, the front wall in 3 pieces around the door, a tilted ceiling; portals: door, stairwell");
    }

    /// <summary>
    /// The cellar below (z in [-3, 0]): floor, four walls, the ceiling around the stairwell, and a ramp
    /// under the stairwell from the floor at x = -1 up to z = 0 at the back-right wall (slope 3 in 4, normal
    /// (-0.6, 0, 0.8): walkable), closed on its open side by a triangle. Portal: the stairwell.
    /// </summary>
    private static CellStructSpec Cellar()
    {
        var m = new MeshBuilder();
        m.Polygon([new(-3, -2.5f, -3), new(3, -2.5f, -3), new(3, 2.5f, -3), new(-3, 2.5f, -3)]);        // floor
        m.Polygon([new(-3, 2.5f, -3), new(3, 2.5f, -3), new(3, 2.5f, 0), new(-3, 2.5f, 0)]);            // back wall
        m.Polygon([new(-3, -2.5f, -3), new(-3, -2.5f, 0), new(3, -2.5f, 0), new(3, -2.5f, -3)]);        // front wall
        m.Polygon([new(3, -2.5f, -3), new(3, -2.5f, 0), new(3, 2.5f, 0), new(3, 2.5f, -3)]);            // right wall
        m.Polygon([new(-3, -2.5f, -3), new(-3, 2.5f, -3), new(-3, 2.5f, 0), new(-3, -2.5f, 0)]);        // left wall
        m.Polygon([new(-3, -2.5f, 0), new(-3, 1, 0), new(3, 1, 0), new(3, -2.5f, 0)]);                 // ceiling before the stairwell
        m.Polygon([new(-3, 1, 0), new(-3, 2.5f, 0), new(-1, 2.5f, 0), new(-1, 1, 0)]);                  // ceiling beside it
        m.Polygon([new(-1, 1, -3), new(3, 1, 0), new(3, 2.5f, 0), new(-1, 2.5f, -3)]);                  // ramp
        m.Polygon([new(-1, 1, -3), new(3, 1, -3), new(3, 1, 0)]);                                        // ramp's side
        var walls = m.PolygonCount;
        m.Polygon([new(-1, 1, 0), new(-1, 2.5f, 0), new(3, 2.5f, 0), new(3, 1, 0)]);                     // portal 0: the stairwell
        return m.ToCellStructSpec(walls, "cellar: floor, 4 walls, ceiling in 2 pieces, ramp and its side; portal: stairwell");
    }

    private static string Hex(uint id) => $"0x{id:X8}";

    /// <summary>An animation of one part, one frame per frame given.</summary>
    private static AnimationSpec OnePartAnimation(uint id, string comment, params FrameSpec[] frames) => new()
    {
        Id = Hex(id),
        Comment = comment,
        Parts = 1,
        Frames = frames.Select(f => (IReadOnlyList<FrameSpec>?)[f]).ToArray(),
    };

    /// <summary>The octagonal column alone, Resting at the origin: the animated one-part Setups.</summary>
    private static SetupSpec ColumnSetup(uint id, string comment) => new()
    {
        Id = Hex(id),
        Comment = comment,
        Parts = [Hex(Column)],
        Placements = Place(("Resting", [At(0, 0, 0)])),
        Radius = 0.4,
        Height = 2,
        Flags = ["HasPhysicsBsp"],
    };

    private static AnimDataSpec Anim(uint id, double framerate = 30, int lowFrame = 0) => new() { Anim = Hex(id), Framerate = framerate, LowFrame = lowFrame };
    /// <summary>
    /// Half of the hook types, with values a reader can get wrong: part indexes above 255, ReplaceObject ids in
    /// the short (offset up to 0x7FFF) and long packed forms, every direction. NoOp is left out: neither public
    /// reader can read past one.
    /// </summary>
    private static IReadOnlyList<HookSpec> OpeningHooks() =>
    [
        Hook("Sound", null, """{"soundId": "0x0A000123"}"""),
        Hook("SoundTable", null, """{"soundType": 7}"""),
        Hook("Attack", "Both", """{"partIndex": 300, "leftX": -0.5, "leftY": 1, "rightX": 0.5, "rightY": 1, "radius": 1.25, "height": 2}"""),
        Hook("AnimationDone", null),
        Hook("ReplaceObject", null, """{"partIndex": 300, "gfxObjId": "0x01000B21"}"""),
        Hook("ReplaceObject", "Backward", """{"partIndex": 2, "gfxObjId": "0x0100C0DE"}"""),
        Hook("Ethereal", null, """{"ethereal": true}"""),
        Hook("TransparentPart", null, """{"partIndex": 1, "start": 0, "end": 0.5, "time": 1.5}"""),
        Hook("Luminous", "Both", """{"start": 0, "end": 1, "time": 0.25}"""),
        Hook("LuminousPart", null, """{"partIndex": 257, "start": 1, "end": 0, "time": 2}"""),
        Hook("Diffuse", "Backward", """{"start": 0.5, "end": 1, "time": 3}"""),
        Hook("DiffusePart", null, """{"partIndex": 3, "start": 0.25, "end": 0.75, "time": 1}"""),
        Hook("Scale", null, """{"end": 1.5, "time": 0.5}"""),
        Hook("CreateParticle", null, """{"emitterInfoId": "0x32000010", "partIndex": 0, "offset": {"origin": [0.5, 0, 1], "orientation": {"w": 0.70710677, "x": 0, "y": 0, "z": 0.70710677}}, "emitterId": 7}"""),
    ];

    /// <summary>The other half, and a long-form ReplaceObject at the smallest long offset (0x8000) last before the CylSpheres.</summary>
    private static IReadOnlyList<HookSpec> ClosingHooks() =>
    [
        Hook("DestroyParticle", null, """{"emitterId": 7}"""),
        Hook("StopParticle", "Both", """{"emitterId": 8}"""),
        Hook("NoDraw", null, """{"noDraw": false}"""),
        Hook("DefaultScript", null),
        Hook("DefaultScriptPart", null, """{"partIndex": 511}"""),
        Hook("CallPES", null, """{"scriptId": "0x33000005", "pause": 0.5}"""),
        Hook("Transparent", "Backward", """{"start": 1, "end": 0, "time": 0.75}"""),
        Hook("SoundTweaked", null, """{"soundId": "0x0A000200", "priority": 0.5, "probability": 0.25, "volume": 0.8}"""),
        Hook("SetOmega", "Both", """{"axis": [0, 0, 1.5]}"""),
        Hook("TextureVelocity", null, """{"uSpeed": 0.5, "vSpeed": -1}"""),
        Hook("TextureVelocityPart", null, """{"partIndex": 300, "uSpeed": 0.25, "vSpeed": 0}"""),
        Hook("SetLight", null, """{"lightsOn": true}"""),
        Hook("CreateBlockingParticle", null, """{"emitterInfoId": "0x32000011", "partIndex": 1, "offset": {"origin": [0, 0, 0.5], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}}, "emitterId": 9}"""),
        Hook("ReplaceObject", null, """{"partIndex": 0, "gfxObjId": "0x01008000"}"""),
    ];

    private static HookSpec Hook(string type, string? direction, string fields = "{}")
    {
        using var document = JsonDocument.Parse(fields);
        return new HookSpec
        {
            Type = type,
            Direction = direction,
            Fields = document.RootElement.EnumerateObject().ToDictionary(p => p.Name, p => p.Value.Clone()),
        };
    }

    private static IReadOnlyDictionary<string, IReadOnlyList<FrameSpec>?> Place(params (string Name, FrameSpec[] Frames)[] placements) =>
        placements.ToDictionary(p => p.Name, p => (IReadOnlyList<FrameSpec>?)p.Frames);

    private static FrameSpec At(double x, double y, double z, QuaternionSpec? q = null) =>
        new() { Origin = [x, y, z], Orientation = q ?? new QuaternionSpec(1, 0, 0, 0) };

    /// <summary>A rotation about Z; exact for multiples of 90 degrees (cos 90° in double is 6e-17, not 0).</summary>
    public static QuaternionSpec Z(double degrees) => new(Half(degrees, cos: true), 0, 0, Half(degrees, cos: false));

    public static QuaternionSpec X(double degrees) => new(Half(degrees, cos: true), Half(degrees, cos: false), 0, 0);

    private static double Half(double degrees, bool cos)
    {
        var half = degrees / 2;
        if (half % 45 == 0)
        {
            var steps = (int)(((half / 45) % 8 + 8) % 8); // 45° units
            double[] c = [1, Math.Sqrt(0.5), 0, -Math.Sqrt(0.5), -1, -Math.Sqrt(0.5), 0, Math.Sqrt(0.5)];
            return cos ? c[steps] : c[(steps + 6) % 8];
        }
        var rad = half * Math.PI / 180;
        return cos ? Math.Cos(rad) : Math.Sin(rad);
    }

    private static MeshBuilder Gem()
    {
        Vector3 top = new(0, 0, 0.16f), bottom = new(0, 0, 0), mid = new(0, 0, 0.08f);
        Vector3[] ring = [mid + new Vector3(0.06f, 0, 0), mid + new Vector3(0, 0.06f, 0), mid + new Vector3(-0.06f, 0, 0), mid + new Vector3(0, -0.06f, 0)];
        var m = new MeshBuilder();
        for (var i = 0; i < 4; i++)
        {
            m.Polygon([ring[i], ring[(i + 1) % 4], top]);
            m.Polygon([ring[(i + 1) % 4], ring[i], bottom]);
        }
        return m;
    }

    private static MeshBuilder LShape()
    {
        // Profile counter-clockwise seen from above; (0, 0.4) splits the long left edge so the top and
        // bottom can be two convex pieces without a T-junction (the block stays watertight).
        Vector2[] profile = [new(0, 0), new(1, 0), new(1, 0.4f), new(0.4f, 0.4f), new(0.4f, 1), new(0, 1), new(0, 0.4f)];
        const float h = 0.6f;
        Vector3 B(Vector2 p) => new(p.X, p.Y, 0);
        Vector3 T(Vector2 p) => new(p.X, p.Y, h);
        var m = new MeshBuilder();
        for (var i = 0; i < profile.Length; i++)
        {
            var a = profile[i];
            var b = profile[(i + 1) % profile.Length];
            m.Polygon([B(a), B(b), T(b), T(a)]);
        }
        int[] pieceA = [0, 1, 2, 3, 6], pieceB = [6, 3, 4, 5];
        m.Polygon(pieceA.Select(i => T(profile[i])));
        m.Polygon(pieceB.Select(i => T(profile[i])));
        m.Polygon(pieceA.Reverse().Select(i => B(profile[i])));
        m.Polygon(pieceB.Reverse().Select(i => B(profile[i])));
        return m;
    }

    /// <summary>
    /// 10 x 8 x 3 m walls on a 1 m grid (x in [-5, 5], y in [-4, 4]); a 2 x 2 m door opening in the front
    /// wall (y = -4) and in an interior wall (x = 2); gable roof with its ridge along x at z = 5; four
    /// furniture boxes.
    /// Walls are two-sided (sidesType None) so they stop movement from inside and out.
    /// </summary>
    private static MeshBuilder HouseMesh()
    {
        var m = new MeshBuilder();
        static float X(int i) => -5 + i;
        static float Y(int j) => -4 + j;
        m.Grid((i, j) => new(X(i), Y(j), 0), 10, 8);                                              // floor, faces up
        m.Grid((i, k) => new(X(i), -4, k), 10, 3, "None", (i, k) => i is 4 or 5 && k < 2);          // front, door opening
        m.Grid((k, i) => new(X(i), 4, k), 3, 10, "None");                                         // back
        m.Grid((j, k) => new(5, Y(j), k), 8, 3, "None");                                          // right end
        m.Grid((k, j) => new(-5, Y(j), k), 3, 8, "None");                                         // left end
        m.Grid((j, k) => new(2, Y(j), k), 8, 3, "None", (j, k) => j is 3 or 4 && k < 2);          // interior wall, doorway
        m.Grid((i, j) => new(X(i), -4 + j, 3 + 0.5f * j), 10, 4);                                 // roof, front slope
        m.Grid((i, j) => new(X(i), j, 5 - 0.5f * j), 10, 4);                                      // roof, back slope
        m.Polygon([new(5, -4, 3), new(5, 4, 3), new(5, 0, 5)], "None");                           // gable ends
        m.Polygon([new(-5, 4, 3), new(-5, -4, 3), new(-5, 0, 5)], "None");
        // Furniture on whole-metre lines: their side planes fall between tiles, so they split the tile
        // sets without spanning them and the tree grows deep instead of ending in 80-tile leaves.
        m.Box(new(-4, 2, 0), new(-3, 3, 3));                                                      // stove and chimney
        m.Box(new(-2, 1, 0), new(0, 3, 0.5f));                                                    // bed
        m.Box(new(3, -2, 0), new(4, -1, 1));                                                      // table
        m.Box(new(3, 2, 0), new(4, 3, 0.7f));                                                     // chest
        return m;
    }

    private static MeshBuilder OddMesh()
    {
        var m = new MeshBuilder().Box(new(-1, -1, 0), new(1, 1, 2));
        m.Polygon([new(-1, 0, 2.5f), new(0, 0, 2.5f), new(1, 0, 2.5f)]);                       // collinear: no plane
        m.Polygon([new(-1, -1, 3), new(1, -1, 3), new(1, 1, 3.2f), new(-1, 1, 3)]);              // 0.2 m out of plane
        return m;
    }
}
