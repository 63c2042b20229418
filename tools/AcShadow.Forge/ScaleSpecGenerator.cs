using AcShadow.Core.Catalog;
using System.Numerics;
using AcShadow.Forge.Geometry;
using AcShadow.Forge.Spec;

namespace AcShadow.Forge;

/// <summary>
/// A realistic-scale spec for benchmarks, generated from a seed (same seed and count, same spec, same
/// bytes). Mix, for the default 2000 Setups and about 3000 GfxObjs: doors (3 parts: leaf + two jambs,
/// every door-setups.tsv id among them), statics with 1-8 physics parts of 10-300 polygons (subdivided
/// boxes, walls, prisms, compounds), creatures with CylSpheres over drawing-only parts, items with Spheres,
/// and landblocks placing them.
/// </summary>
public static class ScaleSpecGenerator
{
    public const int DefaultSetups = 2000;
    public const int DefaultSeed = 1;
    public const int MaxSetups = 20000;
    private const int JambVariants = 16;

    public static ForgeSpec Generate(int setups = DefaultSetups, int seed = DefaultSeed)
    {
        if (setups < 1 || setups > MaxSetups) throw new ArgumentOutOfRangeException(nameof(setups), setups, $"setups must be 1-{MaxSetups}");
        var random = new Random(seed);
        var gfxObjs = new List<GfxObjSpec>();
        var setupSpecs = new List<SetupSpec>();
        var nextGfx = 0x01000100u;
        uint NewGfxId() => nextGfx++;

        var doorIds = DoorCatalog.SetupIds;
        var doorCount = Math.Min(setups, Math.Max(doorIds.Count, setups / 10));
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
        var extraDoors = new List<uint>();
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

        // Physics pool for statics (about 0.9 per Setup) and a drawing-only pool (about 0.45 per Setup).
        var physicsPool = new List<(uint Id, float Size)>();
        for (var i = 0; i < Math.Max(1, setups * 9 / 10); i++)
        {
            var id = NewGfxId();
            var (mesh, size) = PhysicsShape(random);
            gfxObjs.Add(mesh.ToSpec(id, true, random.Next(5) != 0));
            physicsPool.Add((id, size));
        }
        var drawingPool = new List<(uint Id, float Size)>();
        for (var i = 0; i < Math.Max(1, setups * 45 / 100); i++)
        {
            var id = NewGfxId();
            var size = (float)Range(random, 0.1, 0.8);
            var mesh = random.Next(2) == 0
                ? new MeshBuilder().Box(new(-size / 2, -size / 3, 0), new(size / 2, size / 3, size))
                : new MeshBuilder().Prism(Vector3.Zero, size / 2, size, random.Next(6, 13));
            gfxObjs.Add(mesh.ToSpec(id, false, true));
            drawingPool.Add((id, size));
        }

        var physicsCursor = 0;
        (uint Id, float Size) NextPhysics() => physicsCursor < physicsPool.Count ? physicsPool[physicsCursor++] : physicsPool[random.Next(physicsPool.Count)];
        var drawingCursor = 0;
        (uint Id, float Size) NextDrawing() => drawingCursor < drawingPool.Count ? drawingPool[drawingCursor++] : drawingPool[random.Next(drawingPool.Count)];

        var statics = new List<uint>();
        for (var s = 0; s < staticCount; s++)
        {
            var partCount = random.Next(1, 9);
            var parts = Enumerable.Range(0, partCount).Select(_ => NextPhysics()).ToArray();
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
            var parts = Enumerable.Range(0, random.Next(2, 7)).Select(_ => NextDrawing()).ToArray();
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

        // Landblocks: one per 200 Setups, each placing doors, statics and a few bare GfxObjs.
        var landblocks = new List<LandblockSpec>();
        var placeable = setupSpecs.Select(s => s.Id!).ToArray();
        for (var l = 0; l < Math.Max(1, setups / 200); l++)
        {
            var id = (uint)(((l % 254) << 24) | ((l / 254) << 16) | 0xFFFE);
            var objects = Enumerable.Range(0, random.Next(10, 31)).Select(_ =>
            {
                var model = random.Next(5) == 0 ? Hex(physicsPool[random.Next(physicsPool.Count)].Id) : placeable[random.Next(placeable.Length)];
                return new StabSpec { Id = model, Origin = [Range(random, 0, 192), Range(random, 0, 192), Range(random, 0, 40)], Orientation = SampleSpecAuthor.Z(random.Next(360)) };
            }).ToArray();
            var buildings = Enumerable.Range(0, random.Next(0, 4)).Select(_ => new BuildingSpec
            {
                ModelId = Hex(physicsPool[random.Next(physicsPool.Count)].Id),
                Origin = [Range(random, 0, 192), Range(random, 0, 192), Range(random, 0, 40)],
                Orientation = SampleSpecAuthor.Z(random.Next(4) * 90),
                NumLeaves = random.Next(1, 8),
            }).ToArray();
            landblocks.Add(new LandblockSpec { Id = Hex(id), Objects = objects, Buildings = buildings });
        }

        return new ForgeSpec
        {
            Iteration = 1,
            Provenance = $"forge scale --setups {setups} --seed {seed}: synthetic geometry; door Setup ids from the ACE world database door list",
            GfxObjs = gfxObjs,
            Setups = setupSpecs,
            Landblocks = landblocks,
        };
    }

    /// <summary>A physics part of 10-300 polygons and its rough size (metres).</summary>
    private static (MeshBuilder Mesh, float Size) PhysicsShape(Random random)
    {
        var m = new MeshBuilder();
        switch (random.Next(4))
        {
            case 0:
            {
                var n = random.Next(2, 8); // 24-294 polygons
                var s = (float)Range(random, 0.3, 3);
                m.Box(new(-s / 2, -s / 2, 0), new(s / 2, s / 2, s), n, n, n);
                return (m, s);
            }
            case 1:
            {
                var length = (float)Range(random, 2, 12);
                var height = (float)Range(random, 1, 4);
                var thick = (float)Range(random, 0.1, 0.6);
                m.Box(new(-length / 2, -thick / 2, 0), new(length / 2, thick / 2, height), random.Next(2, 13), 1, random.Next(1, 11)); // 10-284
                return (m, length);
            }
            case 2:
            {
                var r = (float)Range(random, 0.1, 2);
                var h = (float)Range(random, 0.3, 6);
                m.Prism(Vector3.Zero, r, h, random.Next(8, 25), random.Next(1, 13)); // 10-290
                return (m, Math.Max(2 * r, h));
            }
            default:
            {
                // A compound: a slab top on 2-4 legs (a table, a stall).
                var w = (float)Range(random, 0.8, 4);
                var d = (float)Range(random, 0.6, 3);
                var h = (float)Range(random, 0.6, 2);
                var sub = random.Next(1, 4);
                m.Box(new(-w / 2, -d / 2, h - 0.1f), new(w / 2, d / 2, h), sub, sub, 1);
                var legs = random.Next(2, 5);
                for (var k = 0; k < legs; k++)
                {
                    var x = (k % 2 == 0 ? -1 : 1) * (w / 2 - 0.1f);
                    var y = (k / 2 == 0 ? -1 : 1) * (d / 2 - 0.1f);
                    m.Box(new(x - 0.05f, y - 0.05f, 0), new(x + 0.05f, y + 0.05f, h - 0.1f));
                }
                return (m, Math.Max(w, h));
            }
        }
    }

    private static double Range(Random random, double min, double max) => Math.Round(min + random.NextDouble() * (max - min), 3);

    private static FrameSpec Frame(double x, double y, double z, int degrees) =>
        new() { Origin = [x, y, z], Orientation = SampleSpecAuthor.Z(degrees) };

    private static string Hex(uint id) => $"0x{id:X8}";
}
