using System.Numerics;
using AcShadow.Fixtures.Movement;
using AcShadow.Tests.Collision;
using static AcShadow.Tests.Movement.MovementScenes;

namespace AcShadow.Tests.Movement;

/// <summary>A human walking into a flat wall: head-on it stops within one step and stays stopped; at an angle it slides.</summary>
public class WallTests
{
    /// <summary>A wall 10 m wide, 0.3 m thick, 3 m tall whose face (normal −y in its own frame) passes through its origin.</summary>
    private static MovementObject Wall(Vector3 facePoint, float degrees) =>
        OnePart(TestMesh.Box(new Vector3(0f, 0.15f, 1.5f), new Vector3(5f, 0.15f, 1.5f)), facePoint,
            Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f));

    [Fact]
    public void Head_on_the_mover_stops_within_one_step_of_the_wall_and_stays_stopped()
    {
        // Face at y = 2. Each frame moves 3.12 / 30 = 0.104 m (< r 0.48: one step). Sphere 0 touches the face when
        // 2 − y ≤ r − ε = 0.4798, i.e. y ≥ 1.5202. y = 0.104 k: k = 14 gives 1.456 (clear), k = 15 gives 1.560 (touching),
        // so frame 14 (the 15th) is rejected: the flat face leaves no tangential component (slide |o|² = 0 < ε → Collided),
        // and every later frame's offset is projected on the sliding normal's tangent, (1,0,0)·(0,0.104,0) = 0.
        var frames = MovementReference.Run(Human(), Wall(new Vector3(0f, 2f, 0f), 0f), WalkNorth(0f, 0f, 40));

        Assert.Equal(1.456f, frames[13].Position.Y, 1e-4f);
        for (var f = 14; f < frames.Count; f++)
            Assert.Equal(frames[13].Position, frames[f].Position);
        Assert.True(frames[14].HitObject);
        // Stand-off: 2 − 1.456 − 0.48 = 0.064 m, under one step (0.104).
        var standOff = 2f - frames[^1].Position.Y - 0.48f;
        Assert.InRange(standOff, 0f, 0.104f);
        Assert.Equal(0f, frames[^1].Position.X);
    }

    [Theory]
    [InlineData(30f)]
    [InlineData(60f)]
    public void At_an_angle_the_mover_slides_along_the_wall_with_the_tangential_component(float degrees)
    {
        // The wall turned θ about z: normal n = (sin θ, −cos θ, 0), tangent t = (cos θ, sin θ, 0). Walking +y at
        // 0.104 m a frame, after contact each frame moves by the step's tangential part (0,0.104,0)·t t = 0.104 sin θ t:
        // 30°: 0.052 m a frame (0.0450, 0.0260); 60°: 0.0901 m a frame (0.0450, 0.0780). The distance to the face stays.
        var theta = degrees * MathF.PI / 180f;
        var normal = new Vector3(MathF.Sin(theta), -MathF.Cos(theta), 0f);
        var tangent = new Vector3(MathF.Cos(theta), MathF.Sin(theta), 0f);
        var frames = MovementReference.Run(Human(), Wall(new Vector3(0f, 2f, 0f), degrees), WalkNorth(0f, 0f, 40));

        var first = frames.ToList().FindIndex(f => f.HitObject);
        Assert.InRange(first, 1, 30);
        var expected = tangent * (0.104f * MathF.Sin(theta));
        float Distance(MovementFrame f) => Vector3.Dot(f.Position + new Vector3(0f, 0f, 0.475f) - new Vector3(0f, 2f, 0f), -normal);
        for (var f = first + 1; f < frames.Count; f++)
        {
            var moved = frames[f].Position - frames[f - 1].Position;
            Assert.True(Vector3.Distance(expected, moved) < 1e-4f, $"frame {f} moved {moved}, expected {expected}");
            Assert.Equal(Distance(frames[first]), Distance(frames[f]), 1e-4f);
        }
        Assert.InRange(-Distance(frames[^1]), 0.4798f, 0.48f + 0.104f);
    }
}
