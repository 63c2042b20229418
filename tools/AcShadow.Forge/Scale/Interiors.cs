using AcShadow.Forging;
using AcShadow.Forging.Geometry;
using AcShadow.Forging.Spec;
using static AcShadow.Forge.Scale.SpecValues;

namespace AcShadow.Forge.Scale;

/// <summary>
/// The scale spec's indoors: a few room Environments, and each landblock's EnvCells built from them.
/// Drawn from a Random of their own, so the rest of the spec is the same with or without them.
/// </summary>
internal static class Interiors
{
    public const int EnvironmentCount = 12, MaxCellsPerLandblock = 40;

    /// <summary>The room Environments, and <paramref name="landblocks"/> each given its cells.</summary>
    public static (List<EnvironmentSpec> Environments, List<LandblockSpec> Landblocks) Furnish(
        IEnumerable<LandblockSpec> landblocks, IReadOnlyList<string> placeable, int seed)
    {
        var random = new Random(seed ^ 0x0CE11);
        var environments = Environments(random);
        return (environments, landblocks.Select(l => l with { Cells = Cells(random, environments, placeable) }).ToList());
    }

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
    private static List<CellSpec> Cells(Random random, List<EnvironmentSpec> environments, IReadOnlyList<string> placeable)
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
                    Id = placeable[random.Next(placeable.Count)],
                    Origin = [origin[0] + 1, origin[1] + 1, origin[2]],
                    Orientation = SampleSpecAuthor.Z(random.Next(360)),
                }).ToArray(),
            });
        }
        return cells;
    }
}
