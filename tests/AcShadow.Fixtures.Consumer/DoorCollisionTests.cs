using System.Numerics;
using AcShadow.Fixtures;

namespace DoorCollision.Tests;

/// <summary>
/// The closed door 0x020019FF, loaded from acshadow's fixtures and placed where the landblock puts it.
/// A player-sized sphere walking through the doorway off-centre must be stopped by the door, and one
/// walking past the door must not be.
/// </summary>
public class DoorCollisionTests
{
    private const uint Door = 0x020019FF;
    private const float PlayerRadius = 0.5f;
    private const float WaistHeight = 1.0f;

    private static readonly FixtureSet Fixtures = FixtureSet.Open(FixturesFolder());

    [Fact]
    public void A_sphere_walking_through_the_closed_doorway_off_centre_is_blocked()
    {
        var door = PlaceDoor();
        // 0.6 m to the side of the doorway's centre line: the single soda-can cylinder some clients
        // register for this door lets this walk through.
        var path = Walk(door, lateral: 0.6f);
        Assert.Contains(path, p => door.Overlaps(p, PlayerRadius));
        Assert.False(door.Overlaps(path[0], PlayerRadius));
        Assert.False(door.Overlaps(path[^1], PlayerRadius));
    }

    [Fact]
    public void A_sphere_walking_past_the_door_is_not_blocked()
    {
        var door = PlaceDoor();
        var path = Walk(door, lateral: 4f);
        Assert.DoesNotContain(path, p => door.Overlaps(p, PlayerRadius));
    }

    [Fact]
    public void The_door_is_made_of_its_parts_physics_bsps()
    {
        var door = Fixtures.Setup(Door);
        Assert.Equal(3, door.Shadow.Shapes.Count);
        Assert.Equal([0x010044B5u, 0x010044B6u], door.Bsps.Keys.Order());
        Assert.Empty(door.Diagnostics);
    }

    /// <summary>The door at its world frame from scene.json, or at a frame of our own when the folder has no scene.</summary>
    private static PlacedFixture PlaceDoor()
    {
        var inScene = Fixtures.Scene?.Objects.FirstOrDefault(o => o.Id == Door);
        return inScene is not null
            ? Fixtures.Setup(Door).PlaceAt(inScene.WorldFrame.Position, inScene.WorldFrame.Rotation)
            : Fixtures.Setup(Door).PlaceAt(new Vector3(100f, 200f, 12f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 3f));
    }

    /// <summary>
    /// World points 5 cm apart along a straight walk through the door's plane, from 2 m before it to 2 m past
    /// it. The door stands across its local y axis, so the walk runs along local y at <paramref name="lateral"/>
    /// metres along local x; the points are turned into the world by the door's own frame.
    /// </summary>
    private static Vector3[] Walk(PlacedFixture door, float lateral)
    {
        var points = new List<Vector3>();
        for (var y = -2f; y <= 2f; y += 0.05f)
            points.Add(door.Position + Vector3.Transform(new Vector3(lateral, y, WaistHeight), door.Rotation));
        return [.. points];
    }

    /// <summary>$ACSHADOW_FIXTURES, else the nearest fixtures/ folder above the test's output folder.</summary>
    private static string FixturesFolder()
    {
        if (Environment.GetEnvironmentVariable("ACSHADOW_FIXTURES") is { Length: > 0 } set) return set;
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "fixtures");
            if (File.Exists(Path.Combine(candidate, "index.json"))) return candidate;
        }
        throw new DirectoryNotFoundException("no fixtures folder: set ACSHADOW_FIXTURES to a folder `acshadow batch` wrote");
    }
}
