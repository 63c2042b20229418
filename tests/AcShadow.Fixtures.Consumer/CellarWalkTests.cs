using System.Numerics;
using AcShadow.Fixtures;

namespace DoorCollision.Tests;

/// <summary>
/// The sample landblock's cottage, loaded from acshadow's committed fixtures: a ground-floor cell with a
/// door to the outside and a stairwell, and a cellar below reached by a ramp. A player-sized sphere walks
/// in from outside, through the doorway, across the room, down the ramp and onto the cellar floor without
/// touching anything; every wall, floor and ceiling polygon stops a sphere exactly where the polygon is.
/// Both cells share one frame, so the walk is written in the ground floor's own coordinates.
/// </summary>
public class CellarWalkTests
{
    private const uint GroundFloor = 0xA9B40100, Cellar = 0xA9B40101;
    private const float PlayerRadius = 0.48f;
    private const float Clearance = 0.05f;

    private static readonly FixtureSet Fixtures = FixtureSet.Open(FixturesFolder());

    [Fact]
    public void The_landblock_lists_both_cells_of_the_cottage()
    {
        var cells = Fixtures.SceneCells();
        Assert.Equal([GroundFloor, Cellar], cells.Select(c => c.CellId));
        var ground = Fixtures.Cell(GroundFloor).File;
        Assert.Contains(ground.Portals, p => p.LeadsOutside);
        Assert.Contains(ground.Portals, p => p.OtherCellId == Cellar);
        Assert.Contains(Fixtures.Cell(Cellar).File.Portals, p => p.OtherCellId == GroundFloor);
    }

    [Fact]
    public void A_sphere_walks_from_outside_through_the_doorway_and_down_into_the_cellar_untouched()
    {
        var ground = Fixtures.Cell(GroundFloor);
        var path = Path();
        Assert.All(path, p => Assert.False(Blocked(ground.ToLandblock(p), PlayerRadius), $"blocked at cell-local {p}"));

        // The walk really goes where the portals are: through the door's polygon and the stairwell's.
        var door = ground.File.Portals.Single(p => p.LeadsOutside);
        var stairwell = ground.File.Portals.Single(p => p.OtherCellId == Cellar);
        Assert.Contains(Crossings(path, door.Plane!.Value), x => Inside(x, door.Vertices));
        Assert.Contains(Crossings(path, stairwell.Plane!.Value), x => Inside(x, stairwell.Vertices));
        Assert.True(path[0].Y < -3f && path[^1].Z < -2f, "starts outside the front wall, ends on the cellar floor");
    }

    [Fact]
    public void Every_wall_floor_ramp_and_ceiling_stops_a_sphere_exactly_where_its_polygon_is()
    {
        const float r = 0.25f, margin = 0.005f;
        foreach (var cell in new[] { Fixtures.Cell(GroundFloor), Fixtures.Cell(Cellar) })
        {
            var physics = cell.File.Physics;
            Assert.NotEmpty(physics.Polygons);
            foreach (var polygon in physics.Polygons)
            {
                var points = polygon.VertexIds.Select(id => physics.Vertices.Single(v => v.Id == id).Position).ToArray();
                var centre = points.Aggregate(Vector3.Zero, (a, b) => a + b) / points.Length;
                var normal = polygon.Plane!.Value.Normal;
                var near = cell.ToLandblock(centre + normal * (r - margin));
                var far = cell.ToLandblock(centre + normal * (r + margin));
                Assert.True(cell.Overlaps(near, r), $"0x{cell.CellId:X8} polygon {polygon.Id}: a sphere {r - margin} m in front of it is not stopped");
                Assert.False(cell.Overlaps(far, r), $"0x{cell.CellId:X8} polygon {polygon.Id}: a sphere {r + margin} m in front of it is stopped");
            }
        }
    }

    [Fact]
    public void The_doorway_is_open_to_its_jambs_and_no_further()
    {
        var ground = Fixtures.Cell(GroundFloor);
        var door = ground.File.Portals.Single(p => p.LeadsOutside);
        var left = door.Vertices.Min(v => v.X);
        var right = door.Vertices.Max(v => v.X);
        var wallY = door.Vertices[0].Y;
        const float z = 1f, margin = 0.01f;
        Assert.False(Blocked(ground.ToLandblock(new Vector3((left + right) / 2, wallY, z)), PlayerRadius));
        Assert.True(Blocked(ground.ToLandblock(new Vector3(left + PlayerRadius - margin, wallY, z)), PlayerRadius));
        Assert.False(Blocked(ground.ToLandblock(new Vector3(left + PlayerRadius + margin, wallY, z)), PlayerRadius));
        Assert.True(Blocked(ground.ToLandblock(new Vector3(right - PlayerRadius + margin, wallY, z)), PlayerRadius));
        Assert.False(Blocked(ground.ToLandblock(new Vector3(right - PlayerRadius - margin, wallY, z)), PlayerRadius));
    }

    [Fact]
    public void The_object_inside_the_room_blocks_and_world_queries_agree_with_landblock_ones()
    {
        var ground = Fixtures.Cell(GroundFloor);
        var inside = Assert.Single(Fixtures.PlaceCellObjects(ground));
        // The L-block stands on the floor from its origin; a small sphere in its corner block is inside it.
        Assert.True(inside.Overlaps(inside.Position + Vector3.Transform(new Vector3(0.2f, 0.2f, 0.3f), inside.Rotation), 0.05f));
        Assert.False(inside.Overlaps(inside.Position + Vector3.Transform(new Vector3(0.2f, 0.2f, 1.5f), inside.Rotation), 0.05f));

        var worldOffset = ground.File.WorldFrame.Position - ground.File.LandblockFrame.Position;
        foreach (var local in new[] { new Vector3(0, 0, 0.2f), new Vector3(0, 0, 0.4f), new Vector3(2.9f, 0, 1), new Vector3(2.7f, 0, 1) })
        {
            var landblock = ground.ToLandblock(local);
            Assert.Equal(ground.Overlaps(landblock, 0.25f), ground.OverlapsWorld(landblock + worldOffset, 0.25f));
        }
    }

    /// <summary>What a sphere inside the cottage can touch: both cells and the object placed in the ground floor.</summary>
    private static bool Blocked(Vector3 landblockPoint, float radius) =>
        Fixtures.SceneCells().Any(c => c.Overlaps(landblockPoint, radius))
        || Fixtures.PlaceCellObjects(Fixtures.Cell(GroundFloor)).Any(o => o.Overlaps(landblockPoint, radius));

    /// <summary>
    /// The walk, 2 cm a step, in the ground floor's own frame (x across, y into the house, z up): from 1.5 m
    /// outside the door to the middle of the room, to the right side, over the stairwell, down the ramp
    /// (which falls toward -x with normal (-0.6, 0, 0.8)) keeping the sphere 5 cm off it, then onto the
    /// cellar floor and across it.
    /// </summary>
    private static Vector3[] Path()
    {
        var h = PlayerRadius + Clearance;
        var rampNormal = new Vector3(-0.6f, 0, 0.8f);
        Vector3 OnRamp(float x) => new Vector3(x, 1.75f, -3f + 0.75f * (x + 1f)) + rampNormal * h;
        Vector3[] corners =
        [
            new(0, -4, h), new(0, 0, h), new(2.3f, 0, h), new(2.3f, 1.75f, h),
            OnRamp(2.3f), OnRamp(0f), new(-2, 1.75f, -3 + h), new(-2, -1, -3 + h),
        ];
        var points = new List<Vector3>();
        for (var i = 0; i + 1 < corners.Length; i++)
        {
            var steps = (int)MathF.Ceiling(Vector3.Distance(corners[i], corners[i + 1]) / 0.02f);
            for (var k = 0; k < steps; k++) points.Add(Vector3.Lerp(corners[i], corners[i + 1], k / (float)steps));
        }
        points.Add(corners[^1]);
        return [.. points];
    }

    /// <summary>Where consecutive path points pass through a plane.</summary>
    private static IEnumerable<Vector3> Crossings(Vector3[] path, Plane plane)
    {
        for (var i = 0; i + 1 < path.Length; i++)
        {
            float a = Plane.DotCoordinate(plane, path[i]), b = Plane.DotCoordinate(plane, path[i + 1]);
            if (a == b || (a > 0) == (b > 0)) continue;
            yield return Vector3.Lerp(path[i], path[i + 1], a / (a - b));
        }
    }

    /// <summary>Inside the axis box of a flat portal polygon (the cottage's are rectangles), 1 mm slack.</summary>
    private static bool Inside(Vector3 p, IReadOnlyList<Vector3> polygon)
    {
        var min = polygon.Aggregate(Vector3.Min) - new Vector3(0.001f);
        var max = polygon.Aggregate(Vector3.Max) + new Vector3(0.001f);
        return p.X >= min.X && p.Y >= min.Y && p.Z >= min.Z && p.X <= max.X && p.Y <= max.Y && p.Z <= max.Z;
    }

    /// <summary>$ACSHADOW_FIXTURES, else the nearest fixtures/ folder above the test's output folder.</summary>
    private static string FixturesFolder()
    {
        if (Environment.GetEnvironmentVariable("ACSHADOW_FIXTURES") is { Length: > 0 } set) return set;
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = System.IO.Path.Combine(dir.FullName, "fixtures");
            if (File.Exists(System.IO.Path.Combine(candidate, "index.json"))) return candidate;
        }
        throw new DirectoryNotFoundException("no fixtures folder: set ACSHADOW_FIXTURES to a folder `acshadow batch` wrote");
    }
}
