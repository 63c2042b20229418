using System.Numerics;
using AcShadow.Analysis.Chart.Movement;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Tests.Chart.Movement;

/// <summary>
/// Each verdict of movement.md §4.2 from a hand-made pair of walks: a mover walking north from the origin at
/// 3 m/s for 20 frames, the gate the plane y = 2; each walk's frames go evenly from the start to its end.
/// </summary>
public class MovementJudgeTests
{
    private static readonly Mover Person = new([new Sphere(new Vector3(0f, 0f, 0.475f), 0.48f), new Sphere(new Vector3(0f, 0f, 1.35f), 0.48f)], 0.6f, 1.5f);
    private static readonly Walk North = new(new Vector3(0f, 0f, 0f), new Vector3(0f, 3f, 0f), 0f, 20, 0.05f);
    private static readonly Plane Gate = new(Vector3.UnitY, -2f);

    /// <summary>Frames from the start to <paramref name="end"/> in equal moves; the last ones carry <paramref name="normal"/> as the collision normal.</summary>
    private static MovementFrame[] Frames(Vector3 end, Vector3? normal = null)
    {
        const int frames = 20;
        var result = new MovementFrame[frames];
        for (var f = 0; f < frames; f++)
        {
            var p = Vector3.Lerp(North.Start, end, (f + 1) / (float)frames);
            var floor = new Plane(Vector3.UnitZ, -p.Z);
            result[f] = new MovementFrame(f, true, 1, p, true, true, floor, null, f >= frames - 3 ? normal : null, normal is not null && f >= frames - 3);
        }
        return result;
    }

    private static MovementCase Reference(MovementFrame[] frames) =>
        new("test", "closed", 0f, North, Gate, frames, MovementOutcome.Of(North, frames, Gate), false, float.PositiveInfinity);

    private static readonly Vector3 Wall = new(0f, -1f, 0f);

    private static MovementVerdict Judge(MovementFrame[] reference, MovementFrame[] candidate, Func<Vector3, float, bool>? occupied = null) =>
        MovementJudge.Judge(Reference(reference), candidate, Person, occupied);

    [Fact]
    public void The_same_walk_agrees()
    {
        var blocked = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        Assert.Equal(MovementVerdict.Agree, Judge(blocked, Frames(new Vector3(0f, 1.5f, 0f), Wall)));
        Assert.Equal(MovementVerdict.Agree, Judge(blocked, Frames(new Vector3(0f, 1.53f, 0f), Wall)));
    }

    [Fact]
    public void Crossing_the_gate_the_reference_does_not_is_a_false_pass()
    {
        Assert.Equal(MovementVerdict.FalsePass, Judge(Frames(new Vector3(0f, 1.5f, 0f), Wall), Frames(new Vector3(0f, 3f, 0f))));
    }

    [Fact]
    public void Standing_where_retail_geometry_is_is_a_false_pass_even_short_of_the_gate()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        var candidate = Frames(new Vector3(0f, 1.52f, 0f), Wall);
        // Retail's geometry begins at y = 1.94: a sphere (shrunk by 5 cm to 0.43 m) reaching past it overlaps.
        bool Occupied(Vector3 c, float r) => c.Y + r > 1.94f;
        Assert.Equal(MovementVerdict.FalsePass, Judge(reference, candidate, Occupied));
        Assert.Equal(MovementVerdict.Agree, Judge(reference, Frames(new Vector3(0f, 1.45f, 0f), Wall), Occupied));
        Assert.Equal(MovementVerdict.Agree, Judge(reference, candidate));
    }

    [Fact]
    public void Getting_past_the_face_that_blocks_the_reference_is_a_false_pass()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        Assert.Equal(MovementVerdict.FalsePass, Judge(reference, Frames(new Vector3(0f, 1.6f, 0f), Wall)));
        // Sideways along the face is not past it.
        Assert.NotEqual(MovementVerdict.FalsePass, Judge(reference, Frames(new Vector3(0.3f, 1.5f, 0f), Wall)));
    }

    [Fact]
    public void Not_crossing_where_the_reference_crosses_or_falling_short_of_it_is_a_false_block()
    {
        Assert.Equal(MovementVerdict.FalseBlock, Judge(Frames(new Vector3(0f, 3f, 0f)), Frames(new Vector3(0f, 1.5f, 0f), Wall)));
        Assert.Equal(MovementVerdict.FalseBlock, Judge(Frames(new Vector3(0f, 1.9f, 0f)), Frames(new Vector3(0f, 1.8f, 0f))));
    }

    [Fact]
    public void Standing_still_on_a_frame_where_the_reference_moves_is_a_false_block()
    {
        var reference = Frames(new Vector3(0f, 1.9f, 0f));
        var candidate = Frames(new Vector3(0f, 1.9f, 0f));
        // Frame 5 repeats frame 4 (a failed transition keeps the position), then catches up on frame 6.
        candidate[5] = candidate[5] with { Position = candidate[4].Position, Valid = false };
        Assert.Equal(MovementVerdict.FalseBlock, Judge(reference, candidate));
    }

    [Fact]
    public void Ending_more_than_ten_centimetres_to_the_side_short_of_the_gate_is_a_deflection()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        Assert.Equal(MovementVerdict.Deflection, Judge(reference, Frames(new Vector3(0.2f, 1.5f, 0f), Wall)));
    }

    [Fact]
    public void Travelling_in_a_direction_more_than_ten_degrees_off_at_the_end_is_a_deflection()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        var candidate = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        // Same end, but the last move runs 45° off north.
        candidate[^2] = candidate[^2] with { Position = new Vector3(-0.05f, 1.45f, 0f) };
        Assert.Equal(MovementVerdict.Deflection, Judge(reference, candidate));
    }

    [Fact]
    public void Ending_higher_or_lower_than_the_reference_is_a_step_mismatch()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        Assert.Equal(MovementVerdict.StepMismatch, Judge(reference, Frames(new Vector3(0f, 1.5f, 0.04f), Wall)));
        Assert.Equal(MovementVerdict.StepMismatch, Judge(Frames(new Vector3(0f, 3f, 0.3f)), Frames(new Vector3(0f, 3f, 0f))));
    }

    [Fact]
    public void Ending_more_than_five_centimetres_away_without_another_verdict_is_stand_off_drift()
    {
        var reference = Frames(new Vector3(0f, 1.5f, 0f), Wall);
        Assert.Equal(MovementVerdict.StandOffDrift, Judge(reference, Frames(new Vector3(0.08f, 1.5f, 0f), Wall)));
        Assert.Equal(MovementVerdict.StandOffDrift, Judge(Frames(new Vector3(0f, 3f, 0f)), Frames(new Vector3(0f, 3.08f, 0f))));
    }

    [Fact]
    public void The_first_diverging_frame_is_the_first_whose_position_or_state_parts()
    {
        var reference = Frames(new Vector3(0f, 3f, 0f));
        Assert.Null(MovementJudge.FirstDivergingFrame(reference, Frames(new Vector3(0f, 3f, 0f))));
        var candidate = Frames(new Vector3(0f, 3f, 0f));
        candidate[7] = candidate[7] with { Contact = false };
        candidate[9] = candidate[9] with { Position = candidate[9].Position + new Vector3(0.002f, 0f, 0f) };
        Assert.Equal(7, MovementJudge.FirstDivergingFrame(reference, candidate));
        Assert.Equal(12, MovementJudge.FirstDivergingFrame(reference, reference[..12]));
    }
}
