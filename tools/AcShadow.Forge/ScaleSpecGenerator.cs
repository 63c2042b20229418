using AcShadow.Core.Catalog;
using System.Numerics;
using AcShadow.Forging.Geometry;
using AcShadow.Forging;
using AcShadow.Forging.Spec;

namespace AcShadow.Forge;

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
    private const int JambVariants = 16;

    /// <summary>The GfxObj count <see cref="Generate"/> uses when none is given: the default dat's ratio.</summary>
    public static int GfxObjsFor(int setups) => (int)Math.Min(MaxGfxObjs, Math.Max(MinGfxObjs(setups), (long)setups * DefaultGfxObjs / DefaultSetups));

    /// <summary>The fewest GfxObjs a dat of this many Setups can have: jambs, a leaf per door, one of each pool.</summary>
    public static int MinGfxObjs(int setups) => JambVariants + DoorCount(setups) + 4;

    private static int DoorCount(int setups) => Math.Min(setups, Math.Max(DoorCatalog.SetupIds.Count, setups / 10));

    public static ForgeSpec Generate(int setups = DefaultSetups, int seed = DefaultSeed, int? gfxObjCount = null)
    {
        if (setups < 1 || setups > MaxSetups) throw new ArgumentOutOfRangeException(nameof(setups), setups, $"setups must be 1-{MaxSetups}");
        var totalGfx = gfxObjCount ?? GfxObjsFor(setups);
        if (totalGfx < MinGfxObjs(setups) || totalGfx > MaxGfxObjs)
            throw new ArgumentOutOfRangeException(nameof(gfxObjCount), totalGfx, $"gfxObjs must be {MinGfxObjs(setups)}-{MaxGfxObjs} for {setups} Setups");
        var random = new Random(seed);
        var gfxObjs = new List<GfxObjSpec>(totalGfx);
        var setupSpecs = new List<SetupSpec>(setups);
        var nextGfx = 0x01000100u;
        uint NewGfxId() => nextGfx++;

        var doorIds = DoorCatalog.SetupIds;
        var doorCount = DoorCount(setups);
        var rest = setups - doorCount;
        var staticCount = rest * 45 / 100;
        var creatureCount = rest * 35 / 100;
        var itemCount = rest - staticCount - creatureCount;

        // Non-door Setup ids: sequential, skipping the door ids.
        var taken = new HashSet<uint>(doorIds);
        var nextSetup = 0x02002000u;
        uint NewSetupId()
        {
            while (taken.Contains(nextSetup)) nextSetup++;
            taken.Add(nextSetup);
            return nextSetup++;
        }

        // Doors: a leaf of their own, jambs shared from a few variants (one per doorway width).
        var jambs = new List<(uint Id, float Width)>();
        for (var v = 0; v < JambVariants; v++)
        {
            var width = 1.0f + 0.1f * v;
            var id = NewGfxId();
            gfxObjs.Add(new MeshBuilder()
                .Box(new(-0.05f, -0.15f, 0), new(0.05f, 0.15f, 2.4f + 0.05f * v))
                .Polygon([new(0, 0, 0), new(-width, 0, 0), new(-width, 0, 0.3f), new(0, 0, 0.3f)])
                .ToSpec(id, true, true));
            jambs.Add((id, width));
        }
        for (var d = 0; d < doorCount; d++)
        {
            var setupId = d < doorIds.Count ? doorIds[d] : NewSetupId();
            var (jamb, width) = jambs[random.Next(jambs.Count)];
            var half = width / 2 - 0.035f;
            var thick = (float)Range(random, 0.05, 0.3);
            var leafId = NewGfxId();
            var subdivide = random.Next(4) == 0 ? random.Next(2, 5) : 1;
            gfxObjs.Add(new MeshBuilder()
                .Box(new(-half, -thick / 2, 0), new(half, thick / 2, 2.2f), subdivide, 1, subdivide)
                .ToSpec(leafId, true, true));
            var hingeX = width / 2 - 0.035f;
            setupSpecs.Add(new SetupSpec
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

        // The rest of the GfxObjs: a physics pool (statics' parts), a drawing-only pool (creatures' and
        // items' parts) and a bare pool no Setup uses (landblocks place some of it directly).
        var remaining = totalGfx - gfxObjs.Count;
        var physicsCount = Math.Max(1, remaining * 40 / 100);
        var bareCount = Math.Max(2, remaining * 10 / 100);
        var drawingCount = remaining - physicsCount - bareCount;
        var physicsPool = new List<(uint Id, float Size)>(physicsCount);
        for (var i = 0; i < physicsCount; i++)
        {
            var id = NewGfxId();
            var (mesh, size) = PhysicsShape(random, PhysicsPolygonCount(random));
            gfxObjs.Add(mesh.ToSpec(id, true, random.Next(5) != 0));
            physicsPool.Add((id, size));
        }
        var drawingPool = new List<(uint Id, float Size)>(drawingCount);
        for (var i = 0; i < drawingCount; i++)
        {
            var id = NewGfxId();
            var (mesh, size) = DrawingShape(random);
            gfxObjs.Add(mesh.ToSpec(id, false, true));
            drawingPool.Add((id, size));
        }
        var barePhysics = new List<uint>();
        for (var i = 0; i < bareCount; i++)
        {
            var id = NewGfxId();
            if (i % 2 == 0)
            {
                gfxObjs.Add(PhysicsShape(random, PhysicsPolygonCount(random)).Mesh.ToSpec(id, true, true));
                barePhysics.Add(id);
            }
            else gfxObjs.Add(DrawingShape(random).Mesh.ToSpec(id, false, true));
        }

        // Each pool entry is used once in order first, then at random: every GfxObj of a pool is used and
        // the later draws share (a real dat reuses rocks, walls and limbs across many Setups).
        var physicsCursor = 0;
        (uint Id, float Size) NextPhysics() => physicsCursor < physicsPool.Count ? physicsPool[physicsCursor++] : physicsPool[random.Next(physicsPool.Count)];
        var drawingCursor = 0;
        (uint Id, float Size) NextDrawing() => drawingCursor < drawingPool.Count ? drawingPool[drawingCursor++] : drawingPool[random.Next(drawingPool.Count)];

        var statics = new List<uint>();
        for (var s = 0; s < staticCount; s++)
        {
            var partCount = PartCount(random, 1);
            // One static in eight also carries a drawing-only part (a banner on a wall): no shape from it.
            var parts = Enumerable.Range(0, partCount).Select(k => k > 0 && random.Next(8) == 0 ? NextDrawing() : NextPhysics()).ToArray();
            var frames = new List<FrameSpec>();
            var z = 0.0;
            foreach (var part in parts)
            {
                frames.Add(Frame(Range(random, -1, 1), Range(random, -1, 1), z, random.Next(24) * 15));
                z += part.Size * 0.5;
            }
            var extent = parts.Max(p => p.Size) + 1.5;
            var placement = random.Next(10) switch { 0 => "Default", 1 => "Other", _ => "Resting" };
            var id = NewSetupId();
            statics.Add(id);
            setupSpecs.Add(new SetupSpec
            {
                Id = Hex(id),
                Parts = parts.Select(p => Hex(p.Id)).ToArray(),
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?> { [placement] = frames },
                DefaultScale = random.Next(5) == 0 ? parts.Select(_ => new[] { Range(random, 0.5, 2), Range(random, 0.5, 2), Range(random, 0.5, 2) }).ToArray() : null,
                Radius = Math.Round(extent, 3),
                Height = Math.Round(z + parts[^1].Size, 3),
                Flags = random.Next(10) == 0 ? [] : ["HasPhysicsBsp"],
            });
        }

        for (var c = 0; c < creatureCount; c++)
        {
            var parts = Enumerable.Range(0, PartCount(random, 2)).Select(_ => NextDrawing()).ToArray();
            var radius = Range(random, 0.3, 1.2);
            var height = Range(random, 1.0, 3.0);
            var cyls = new List<CylSphereSpec> { new() { Origin = [0, 0, 0], Radius = radius, Height = height } };
            if (random.Next(3) == 0) cyls.Add(new CylSphereSpec { Origin = [0, radius / 2, height * 0.8], Radius = radius / 2, Height = height * 0.2 });
            setupSpecs.Add(new SetupSpec
            {
                Id = Hex(NewSetupId()),
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

        for (var i = 0; i < itemCount; i++)
        {
            var part = NextDrawing();
            var spheres = Enumerable.Range(0, random.Next(1, 3))
                .Select(k => new SphereSpec { Center = [0, 0, part.Size / 2 + k * 0.1], Radius = Math.Round(part.Size / 2, 3) }).ToArray();
            setupSpecs.Add(new SetupSpec
            {
                Id = Hex(NewSetupId()),
                Parts = [Hex(part.Id)],
                Placements = new Dictionary<string, IReadOnlyList<FrameSpec>?> { ["Default"] = [Frame(0, 0, 0, 0)] },
                Spheres = spheres,
                Radius = Math.Round(part.Size, 3),
                Height = Math.Round(part.Size, 3),
            });
        }

        // Landblocks: one per 200 Setups, each placing doors, statics, bare GfxObjs and buildings; the first 60 objects.
        var landblocks = new List<LandblockSpec>();
        var placeable = setupSpecs.Select(s => s.Id!).ToArray();
        var bareModels = barePhysics.Count > 0 ? barePhysics : physicsPool.Select(p => p.Id).ToList();
        for (var l = 0; l < Math.Max(1, setups / 200); l++)
        {
            var id = (uint)(((l % 254) << 24) | ((l / 254) << 16) | 0xFFFE);
            // The first landblock is a busy one (60 placed objects, as a town's), so a scene compile is measured at scale.
            var objects = Enumerable.Range(0, l == 0 ? BusyLandblockObjects : random.Next(10, 31)).Select(_ =>
            {
                var model = random.Next(5) == 0 ? Hex(bareModels[random.Next(bareModels.Count)]) : placeable[random.Next(placeable.Length)];
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

        var (motionTables, animations) = ScaleMotions.Assign(setupSpecs[..doorCount], setupSpecs[doorCount..(doorCount + staticCount)],
            setupSpecs[(doorCount + staticCount)..(doorCount + staticCount + creatureCount)], seed);
        // Interiors from a random of their own, so everything above is the same with or without them.
        var interiors = new Random(seed ^ 0x0CE11);
        var environments = Environments(interiors);
        landblocks = landblocks.Select(l => l with { Cells = Cells(interiors, environments, placeable) }).ToList();

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

    public const int EnvironmentCount = 12, MaxCellsPerLandblock = 40;

    /// <summary>
    /// Rooms of 4-12 m by 4-12 m, 3-4 m tall, on a 2 m grid (so 20-150 physics polygons, as retail
    /// cell structures have), walls facing in, a 2 m door in the front wall as the portal polygon.
    /// </summary>
    private static List<EnvironmentSpec> Environments(Random random)
    {
        var environments = new List<EnvironmentSpec>();
        for (var e = 0; e < EnvironmentCount; e++)
        {
            var structs = Enumerable.Range(0, random.Next(1, 5)).Select(_ =>
            {
                int nx = random.Next(2, 7), ny = random.Next(2, 7), nz = 2;
                float w = nx * 2f, d = ny * 2f, h = random.Next(3, 5);
                var door = random.Next(nx);
                float X(int i) => i * 2f;
                float Y(int j) => j * 2f;
                float Z(int k) => k * h / nz;
                var m = new MeshBuilder();
                m.Grid((i, j) => new(X(i), Y(j), 0), nx, ny);                                       // floor, up
                m.Grid((j, i) => new(X(i), Y(j), h), ny, nx);                                       // ceiling, down
                m.Grid((i, k) => new(X(i), d, Z(k)), nx, nz);                                       // back wall
                m.Grid((k, i) => new(X(i), 0, Z(k)), nz, nx, skip: (k, i) => i == door && k == 0);  // front wall, door
                m.Grid((k, j) => new(w, Y(j), Z(k)), nz, ny);                                       // right wall
                m.Grid((j, k) => new(0, Y(j), Z(k)), ny, nz);                                       // left wall
                var walls = m.PolygonCount;
                m.Polygon([new(X(door), 0, 0), new(X(door + 1), 0, 0), new(X(door + 1), 0, Z(1)), new(X(door), 0, Z(1))]);
                return m.ToCellStructSpec(walls);
            }).ToArray();
            environments.Add(new EnvironmentSpec { Id = Hex(0x0D000200u + (uint)e), CellStructs = structs });
        }
        return environments;
    }

    /// <summary>
    /// 0-40 cells a landblock (towns have tens), in buildings of up to four rooms: a building's first cell
    /// opens outside, each next one onto the one before; each sees its neighbours; some hold a Setup or two.
    /// </summary>
    private static List<CellSpec> Cells(Random random, List<EnvironmentSpec> environments, string[] placeable)
    {
        var count = random.Next(MaxCellsPerLandblock + 1);
        var cells = new List<CellSpec>(count);
        for (var i = 0; i < count; i++)
        {
            var environment = environments[random.Next(environments.Count)];
            var origin = new[] { Range(random, 0, 180), Range(random, 0, 180), Range(random, 0, 40) };
            var startsBuilding = i % 4 == 0;
            string Cell(int index) => $"0x{0x0100 + index:X4}";
            var visible = new List<string>();
            if (!startsBuilding) visible.Add(Cell(i - 1));
            if ((i + 1) % 4 != 0 && i + 1 < count) visible.Add(Cell(i + 1));
            cells.Add(new CellSpec
            {
                Environment = environment.Id,
                CellStruct = random.Next(environment.CellStructs.Count),
                Origin = origin,
                Orientation = SampleSpecAuthor.Z(random.Next(4) * 90),
                SeenOutside = startsBuilding,
                Portals = [new CellPortalSpec { Polygon = 0, OtherCell = startsBuilding ? "outside" : Cell(i - 1), Flags = "PortalSide" }],
                VisibleCells = visible,
                Objects = Enumerable.Range(0, random.Next(3)).Select(_ => new StabSpec
                {
                    Id = placeable[random.Next(placeable.Length)],
                    Origin = [origin[0] + 1, origin[1] + 1, origin[2]],
                    Orientation = SampleSpecAuthor.Z(random.Next(360)),
                }).ToArray(),
            });
        }
        return cells;
    }

    /// <summary>
    /// 4 × 500^(u⁴), u uniform: long-tailed from 4 to 2,000 (median 6, about 11 % at 200 or more, 3 % at
    /// 1,000 or more). The shapes below come within a few polygons of it.
    /// </summary>
    private static int PhysicsPolygonCount(Random random)
    {
        var u = random.NextDouble();
        var n = (int)Math.Round(MinPhysicsPolygons * Math.Pow(MaxPhysicsPolygons / (double)MinPhysicsPolygons, u * u * u * u));
        return Math.Clamp(n, MinPhysicsPolygons, MaxPhysicsPolygons);
    }

    /// <summary><paramref name="min"/> to 30 parts, few parts common: min + 29·u³ for statics, wider for creatures.</summary>
    private static int PartCount(Random random, int min)
    {
        var u = random.NextDouble();
        var spread = min == 1 ? u * u * u : u * u;
        return Math.Min(MaxParts, min + (int)((MaxParts - min + 1) * spread));
    }

    /// <summary>A closed physics part of about <paramref name="polygons"/> polygons and its rough size (metres).</summary>
    private static (MeshBuilder Mesh, float Size) PhysicsShape(Random random, int polygons)
    {
        var m = new MeshBuilder();
        if (polygons < 6)
        {
            var s = (float)Range(random, 0.2, 2);
            return (polygons == 4 ? Tetrahedron(m, s) : Pyramid(m, s), s);
        }
        var kind = polygons >= 200 ? random.Next(5) switch { 0 => 0, 1 => 1, 2 => 2, _ => 4 } : random.Next(4);
        switch (kind)
        {
            case 0:
            {
                // A subdivided box: 6 k² polygons on six planes (big leaves, shallow tree).
                var k = Math.Max(1, (int)Math.Round(Math.Sqrt(polygons / 6.0)));
                var s = (float)Range(random, 0.3, 3);
                m.Box(new(-s / 2, -s / 2, 0), new(s / 2, s / 2, s), k, k, k);
                return (m, s);
            }
            case 1:
            {
                // A wall: 2(nx + nz + nx·nz) polygons.
                var length = (float)Range(random, 2, 12);
                var height = (float)Range(random, 1, 4);
                var thick = (float)Range(random, 0.1, 0.6);
                var nz = Math.Max(1, (int)Math.Round(Math.Sqrt(polygons / 8.0)));
                var nx = Math.Max(1, (polygons / 2 - nz) / (nz + 1));
                m.Box(new(-length / 2, -thick / 2, 0), new(length / 2, thick / 2, height), nx, 1, nz);
                return (m, length);
            }
            case 2:
            {
                // A prism (column, tower): sides · rings + 2 polygons.
                var r = (float)Range(random, 0.1, 2);
                var h = (float)Range(random, 0.3, 6);
                var sides = Math.Clamp(polygons - 2, 3, 48);
                var rings = Math.Max(1, (polygons - 2) / sides);
                m.Prism(Vector3.Zero, r, h, sides, rings);
                return (m, Math.Max(2 * r, h));
            }
            case 3:
            {
                // A compound: a slab top on 2-4 legs (a table, a stall), each a closed box.
                var w = (float)Range(random, 0.8, 4);
                var d = (float)Range(random, 0.6, 3);
                var h = (float)Range(random, 0.6, 2);
                var legs = random.Next(2, 5);
                var sub = Math.Max(1, (int)Math.Round(Math.Sqrt(Math.Max(1, polygons - 6 * legs) / 6.0)));
                m.Box(new(-w / 2, -d / 2, h - 0.1f), new(w / 2, d / 2, h), sub, sub, 1);
                for (var k = 0; k < legs; k++)
                {
                    var x = (k % 2 == 0 ? -1 : 1) * (w / 2 - 0.1f);
                    var y = (k / 2 == 0 ? -1 : 1) * (d / 2 - 0.1f);
                    m.Box(new(x - 0.05f, y - 0.05f, 0), new(x + 0.05f, y + 0.05f, h - 0.1f));
                }
                return (m, Math.Max(w, h));
            }
            default:
                return Building(m, random, polygons);
        }
    }

    /// <summary>
    /// A building: rooms, pillars and furniture as separate closed boxes of their own sizes on a floor grid,
    /// so their planes differ and the BSP is deep and branching (6 polygons per box).
    /// </summary>
    private static (MeshBuilder Mesh, float Size) Building(MeshBuilder m, Random random, int polygons)
    {
        var boxes = Math.Max(1, polygons / 6);
        var columns = (int)Math.Ceiling(Math.Sqrt(boxes));
        var cell = (float)Range(random, 1.5, 3);
        for (var b = 0; b < boxes; b++)
        {
            var x0 = b % columns * cell;
            var y0 = b / columns * cell;
            var w = (float)Range(random, 0.15, cell * 0.4);
            var d = (float)Range(random, 0.15, cell * 0.4);
            var h = (float)Range(random, 0.2, 4);
            var cx = x0 + cell / 2 + (float)Range(random, -0.1, 0.1);
            var cy = y0 + cell / 2 + (float)Range(random, -0.1, 0.1);
            m.Box(new(cx - w, cy - d, 0), new(cx + w, cy + d, h));
        }
        return (m, columns * cell);
    }

    /// <summary>4 triangles, outward wound.</summary>
    private static MeshBuilder Tetrahedron(MeshBuilder m, float s)
    {
        Vector3 a = new(0, 0, 0), b = new(s, 0, 0), c = new(0, s, 0), d = new(0, 0, s);
        return m.Polygon([a, c, b]).Polygon([a, b, d]).Polygon([a, d, c]).Polygon([b, c, d]);
    }

    /// <summary>A square pyramid: base and 4 sides, outward wound.</summary>
    private static MeshBuilder Pyramid(MeshBuilder m, float s)
    {
        Vector3 a = new(0, 0, 0), b = new(s, 0, 0), c = new(s, s, 0), d = new(0, s, 0), top = new(s / 2, s / 2, s);
        return m.Polygon([a, d, c, b]).Polygon([a, b, top]).Polygon([b, c, top]).Polygon([c, d, top]).Polygon([d, a, top]);
    }

    /// <summary>A drawing-only part (limb, item): a box or a prism.</summary>
    private static (MeshBuilder Mesh, float Size) DrawingShape(Random random)
    {
        var size = (float)Range(random, 0.1, 0.8);
        var mesh = random.Next(2) == 0
            ? new MeshBuilder().Box(new(-size / 2, -size / 3, 0), new(size / 2, size / 3, size))
            : new MeshBuilder().Prism(Vector3.Zero, size / 2, size, random.Next(6, 13));
        return (mesh, size);
    }

    private static double Range(Random random, double min, double max) => Math.Round(min + random.NextDouble() * (max - min), 3);

    private static FrameSpec Frame(double x, double y, double z, int degrees) =>
        new() { Origin = [x, y, z], Orientation = SampleSpecAuthor.Z(degrees) };

    private static string Hex(uint id) => $"0x{id:X8}";
}
