using System.Numerics;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Tests.Movement.MovementScenes;

namespace AcShadow.Tests.Movement;

/// <summary>Steps within and beyond step-up height, a ledge with and without EdgeSlide, a low cylinder, an ethereal wall.</summary>
public class StepAndLedgeTests
{
    [Fact]
    public void A_step_lower_than_the_step_up_height_is_stepped_onto()
    {
        // A 0.3 m step from y = 2. Sphere 0 (centre z 0.48) touches its top edge when d² + 0.18² ≤ 0.4798², d ≤ 0.4448,
        // y ≥ 1.5552: at k = 15 (y 1.56). Its top face is touched too, so step_up's step-down (0.6 m, walk_interp
        // (1 − (0.48 − 0.3 − 0.48) / −0.6) = 0.5) lifts the sphere onto it: origin z 0.3 + 0.005 = 0.305. Nothing
        // is lost along y: 40 frames reach 4.16.
        var frames = MovementReference.Run(Human(), Block(new Vector3(-2f, 2f, 0f), new Vector3(2f, 10f, 0.3f)), WalkNorth(0f, 0f, 40));

        Assert.Equal(StandingLift, frames[13].Position.Z, 1e-4f);
        Assert.Equal(0.305f, frames[14].Position.Z, 1e-4f);
        Assert.Equal(0.305f, frames[^1].Position.Z, 1e-4f);
        Assert.Equal(4.16f, frames[^1].Position.Y, 1e-3f);
        Assert.True(frames[^1].OnWalkable);
    }

    [Fact]
    public void A_step_higher_than_the_step_up_height_blocks()
    {
        // A 0.8 m step: its face is met like a wall (touch at y ≥ 2 − 0.4798, first at k = 15), and its top face is out
        // of reach: centre 0.32 below its plane, the disc there has radius √(0.4798² − 0.32²) = 0.3575 < 0.44 from the
        // edge. Step-up finds nothing walkable, the head-on slide is Collided: the walker stays at y = 1.456, z 0.005.
        var frames = MovementReference.Run(Human(), Block(new Vector3(-2f, 2f, 0f), new Vector3(2f, 10f, 0.8f)), WalkNorth(0f, 0f, 40));

        Assert.Equal(1.456f, frames[^1].Position.Y, 1e-4f);
        Assert.Equal(StandingLift, frames[^1].Position.Z, 1e-4f);
    }

    private static Walk OffTheLedge(int frames) =>
        WalkNorth(0f, 0f, frames) with { Start = new Vector3(0f, 0f, 2f + StandingLift), StartContact = new Plane(Vector3.UnitZ, -2f) };

    private static MovementObject Platform => Block(new Vector3(-5f, -5f, 0f), new Vector3(5f, 2f, 2f));

    [Fact]
    public void With_EdgeSlide_the_walker_stops_at_the_ledge()
    {
        // A 2 m platform ending at y = 2: no floor within step-down 1.5 beyond it. Each step steps down twice by 0.75
        // onto the top; past the edge check_walkable needs the centre within r/2 = 0.24 of the top polygon, so y ≤ 2.24:
        // y = 0.104 k is 2.184 at k = 21 and 2.288 at k = 22. There the precipice slide along the edge (normal −y)
        // leaves nothing of a head-on step: the walker stays at y = 2.184 on the top, z 2.005.
        var frames = MovementReference.Run(Human(edgeSlide: true), Platform, OffTheLedge(40));

        Assert.Equal(2.184f, frames[^1].Position.Y, 1e-4f);
        Assert.Equal(2f + StandingLift, frames[^1].Position.Z, 1e-4f);
        Assert.True(frames[^1].OnWalkable);
    }

    [Fact]
    public void Without_EdgeSlide_the_walker_walks_off_the_ledge_and_falls_to_the_floor()
    {
        // Without EdgeSlide edge_slide restores the step and drops the contact plane: the walker leaves the top,
        // falls under gravity (9.8 m/s², 2 m takes about 0.64 s, 19 frames) and lands on the floor at z 0.005.
        var frames = MovementReference.Run(Human(edgeSlide: false), Platform, OffTheLedge(60));

        Assert.Contains(frames, f => !f.Contact);
        Assert.True(frames[^1].Position.Y > 2.24f);
        Assert.Equal(StandingLift, frames[^1].Position.Z, 1e-3f);
        Assert.True(frames[^1].OnWalkable);
    }

    [Fact]
    public void A_low_cylinder_is_stepped_onto_not_slid_round()
    {
        // CylSphere r 0.3, h 0.2 at (0, 2, 0): head-on, step-up 0.6 ≥ r + h − Δz = 0.48 + 0.2 − 0.48 = 0.2, so the
        // walker steps onto its top (origin z 0.2 + 0.005 = 0.205), keeps x = 0, and walks on to y = 4.16.
        var shape = new ShadowShape(ShapeSource.CylSphere, 0, null, CollisionType.Cylinder, new Vector3(0f, 2f, 0f), Quaternion.Identity, 1f, 0.3f, 0.2f, null);
        var cylinder = new MovementObject([shape], new Dictionary<uint, CompiledBsp>(), Vector3.Zero, Quaternion.Identity);
        var frames = MovementReference.Run(Human(), cylinder, WalkNorth(0f, 0f, 40));

        Assert.Equal(0.205f, frames.Max(f => f.Position.Z), 1e-4f);
        Assert.All(frames, f => Assert.Equal(0f, f.Position.X));
        Assert.Equal(4.16f, frames[^1].Position.Y, 1e-3f);
    }

    [Fact]
    public void An_ethereal_wall_lets_the_mover_through()
    {
        // The head-on wall of WallTests, ethereal: 40 frames of 0.104 m reach y = 4.16 through it.
        var frames = MovementReference.Run(Human(), Block(new Vector3(-5f, 2f, 0f), new Vector3(5f, 2.3f, 3f), ethereal: true), WalkNorth(0f, 0f, 40));

        Assert.Equal(4.16f, frames[^1].Position.Y, 1e-3f);
        Assert.Contains(frames, f => f.HitObject);
    }
}
