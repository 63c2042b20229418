using System.Numerics;
using AcShadow.Core.Poses;
using AcShadow.Fixtures.Movement;
using static AcShadow.Tests.Movement.MovementScenes;

namespace AcShadow.Tests.Movement;

/// <summary>
/// The sample door 0x020019FF: the closed leaf (a box 1.93 × 0.26 m posed at (0.05, 0, 0), faces at y = ±0.13)
/// stops a walker dead, head-on and 0.45 m off-centre; the open door (ethereal) lets him through; and the door
/// bug (movement.md §5.4): the buggy client's one cylinder does not stop the off-centre walker.
/// </summary>
public class DoorTests
{
    [Theory]
    [InlineData(0f)]
    [InlineData(0.45f)]
    public void The_closed_leaf_stops_the_walker_without_crossing_its_plane(float lateral)
    {
        // From y = −2 at 0.104 m a frame, sphere 0 touches the face y = −0.13 when −0.13 − y ≤ 0.4798, y ≥ −0.6098:
        // y = −2 + 0.104 k is −0.648 at k = 13 (clear) and −0.544 at k = 14 (touching): frame 13 (the 14th) is
        // rejected, the flat face gives no tangential part, and the walker stays at y = −0.648, x unchanged.
        var (door, _) = SampleDoor(DoorState.Closed);
        var frames = MovementReference.Run(Human(), door, WalkNorth(lateral, -2f, 40));

        Assert.Equal(-0.648f, frames[12].Position.Y, 1e-4f);
        for (var f = 13; f < frames.Count; f++) Assert.Equal(frames[12].Position, frames[f].Position);
        Assert.All(frames, f => Assert.True(f.Position.Y + 0.48f < -0.13f));
        Assert.Equal(lateral, frames[^1].Position.X);
    }

    [Fact]
    public void The_open_door_is_ethereal_and_lets_the_walker_through_the_doorway()
    {
        // Opening makes the door ethereal (its pose says so): a hit is answered OK, so 40 frames of 0.104 m take
        // the walker from y = −2 to −2 + 4.16 = 2.16, straight through.
        var (door, set) = SampleDoor(DoorState.Open);
        Assert.True(set.Pose.Ethereal);
        var frames = MovementReference.Run(Human(), door, WalkNorth(0f, -2f, 40));

        Assert.All(frames, f => Assert.True(f.Valid));
        Assert.Equal(2.16f, frames[^1].Position.Y, 1e-3f);
        Assert.Equal(0f, frames[^1].Position.X);
    }

    [Fact]
    public void The_door_bug_the_circle_lets_the_off_centre_walker_past_where_the_leaf_stops_him()
    {
        // The circle: the door's sphere (0,0,0.018) r 0.1 as a cylinder of height 0.2. At x = 0.45 the walker reaches
        // it (0.45 < radsum 0.1 − ε + 0.48 = 0.5798). In contact, CCylSphere::step_sphere_up compares step-up 0.6 with
        // r + h − Δz = 0.48 + 0.2 − (0.48 − 0.018) = 0.218: not less, so he steps onto it (origin z 0.218 + 0.005 = 0.223)
        // and walks on: after 40 frames he is at y = 2.16, past the door plane. The leaf (above) holds him at −0.648.
        var frames = MovementReference.Run(Human(), SampleDoorCircle(), WalkNorth(0.45f, -2f, 40));

        Assert.Equal(2.16f, frames[^1].Position.Y, 1e-3f);
        Assert.Equal(0.223f, frames.Max(f => f.Position.Z), 1e-3f);
        Assert.Equal(StandingLift, frames[^1].Position.Z, 1e-4f);
        var (leaf, _) = SampleDoor(DoorState.Closed);
        Assert.Equal(-0.648f, Human().Run(leaf, WalkNorth(0.45f, -2f, 40))[^1].Position.Y, 1e-4f);
    }
}
