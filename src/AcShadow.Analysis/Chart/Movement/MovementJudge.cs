using System.Numerics;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// Judges a candidate model's walk against the reference's on one case (movement.md §4.2), from their frames
/// and outcomes alone; the first rule that holds is the verdict.
/// <list type="number">
/// <item>False pass: the candidate crossed the gate and the reference did not; or at some frame a mover sphere,
/// shrunk by <see cref="Slack"/>, overlaps the retail geometry (retail's placement query); or the reference was
/// blocked and the candidate got more than <see cref="Slack"/> further along the way the blocking normal opposes.</item>
/// <item>False block: the reference crossed and the candidate did not; or the candidate stood still (or its
/// transition failed) on a frame where the reference moved more than <see cref="Slack"/>; or the reference's
/// progress exceeds the candidate's by more than <see cref="Slack"/>.</item>
/// <item>Deflection: neither crossed, and the lateral ends differ by more than <see cref="LateralTolerance"/> or
/// the last travel directions by more than <see cref="DirectionToleranceDegrees"/>.</item>
/// <item>Step mismatch: the height changes differ by more than <see cref="MovementOutcome.StepTolerance"/>, or one
/// stepped up and the other did not.</item>
/// <item>Stand-off drift: the ends are more than <see cref="Slack"/> apart.</item>
/// </list>
/// </summary>
internal static class MovementJudge
{
    /// <summary>Metres: the placement shrink, and the progress and stand-off allowances (ε and up to one step's stand-off).</summary>
    public const float Slack = 0.05f;

    public const float LateralTolerance = 0.10f;

    public const float DirectionToleranceDegrees = 10f;

    /// <param name="reference">The reference's case (walk, gate, frames, outcome).</param>
    /// <param name="candidate">The candidate's frames on the same walk.</param>
    /// <param name="mover">The mover, for its spheres.</param>
    /// <param name="retailOccupied">
    /// Whether a sphere (landblock-local centre, radius) overlaps the retail geometry (retail's placement query);
    /// null when nothing can be occupied (an ethereal object).
    /// </param>
    public static MovementVerdict Judge(MovementCase reference, IReadOnlyList<MovementFrame> candidate, Mover mover,
        Func<Vector3, float, bool>? retailOccupied)
    {
        ArgumentNullException.ThrowIfNull(reference);
        ArgumentNullException.ThrowIfNull(candidate);
        ArgumentNullException.ThrowIfNull(mover);
        var r = reference.Outcome;
        var c = MovementOutcome.Of(reference.Walk, candidate, reference.Gate);
        var rEnd = End(reference.Walk, reference.Expected);
        var cEnd = End(reference.Walk, candidate);

        if (c.CrossedGate && !r.CrossedGate) return MovementVerdict.FalsePass;
        if (retailOccupied is not null && Occupies(candidate, mover, retailOccupied)) return MovementVerdict.FalsePass;
        if (r.Class == MovementOutcome.Blocked && Beyond(reference, rEnd, cEnd, c) > Slack) return MovementVerdict.FalsePass;

        if (r.CrossedGate && !c.CrossedGate) return MovementVerdict.FalseBlock;
        if (StoodWhereReferenceMoved(reference.Walk.Start, reference.Expected, candidate)) return MovementVerdict.FalseBlock;
        if (r.Progress - c.Progress > Slack) return MovementVerdict.FalseBlock;

        if (!r.CrossedGate && !c.CrossedGate
            && (MathF.Abs(c.Lateral - r.Lateral) > LateralTolerance || Turned(reference.Walk.Start, reference.Expected, candidate)))
            return MovementVerdict.Deflection;

        if (MathF.Abs(c.Dz - r.Dz) > MovementOutcome.StepTolerance
            || (c.Class == MovementOutcome.SteppedUp) != (r.Class == MovementOutcome.SteppedUp))
            return MovementVerdict.StepMismatch;

        return Vector3.Distance(cEnd, rEnd) > Slack ? MovementVerdict.StandOffDrift : MovementVerdict.Agree;
    }

    /// <summary>
    /// The first frame where the two walks part: validity, Contact or OnWalkable differ, or a position axis by more
    /// than the case tolerance (movement.md §2.4); null when they never do.
    /// </summary>
    public static int? FirstDivergingFrame(IReadOnlyList<MovementFrame> reference, IReadOnlyList<MovementFrame> candidate)
    {
        var n = Math.Min(reference.Count, candidate.Count);
        for (var f = 0; f < n; f++)
        {
            var a = reference[f];
            var b = candidate[f];
            var d = a.Position - b.Position;
            if (a.Valid != b.Valid || a.Contact != b.Contact || a.OnWalkable != b.OnWalkable
                || MathF.Abs(d.X) > MovementOutcome.PositionTolerance || MathF.Abs(d.Y) > MovementOutcome.PositionTolerance
                || MathF.Abs(d.Z) > MovementOutcome.PositionTolerance)
                return f;
        }
        return reference.Count == candidate.Count ? null : n;
    }

    /// <summary>Where the walk ended (its start when it has no frames).</summary>
    public static Vector3 End(Walk walk, IReadOnlyList<MovementFrame> frames) => frames.Count > 0 ? frames[^1].Position : walk.Start;

    private static bool Occupies(IReadOnlyList<MovementFrame> frames, Mover mover, Func<Vector3, float, bool> occupied)
    {
        var spheres = mover.Spheres.Count > 0 ? mover.Spheres.Take(2).ToArray() : [MovementConstants.DummySphere];
        foreach (var frame in frames)
            foreach (var s in spheres)
            {
                var radius = s.Radius * mover.Scale - Slack;
                if (radius > 0f && occupied(frame.Position + s.Center * mover.Scale, radius)) return true;
            }
        return false;
    }

    /// <summary>How much further than the reference the candidate ended along the way the reference's last collision normal opposes (along the intent without one).</summary>
    private static float Beyond(MovementCase reference, Vector3 rEnd, Vector3 cEnd, MovementOutcome c)
    {
        var normal = reference.Expected.LastOrDefault(f => f.CollisionNormal is not null)?.CollisionNormal;
        var flat = normal is { } n ? new Vector3(-n.X, -n.Y, 0f) : Vector3.Zero;
        var length = flat.Length();
        if (!(length > 1e-3f)) return c.Progress - reference.Outcome.Progress;
        var d = cEnd - rEnd;
        return (d.X * flat.X + d.Y * flat.Y) / length;
    }

    /// <summary>A frame where the candidate did not move (or its transition failed) while the reference moved more than <see cref="Slack"/>.</summary>
    private static bool StoodWhereReferenceMoved(Vector3 start, IReadOnlyList<MovementFrame> reference, IReadOnlyList<MovementFrame> candidate)
    {
        var n = Math.Min(reference.Count, candidate.Count);
        for (var f = 0; f < n; f++)
        {
            var rMoved = Vector3.Distance(reference[f].Position, f == 0 ? start : reference[f - 1].Position);
            if (!(rMoved > Slack)) continue;
            var cMoved = Vector3.Distance(candidate[f].Position, f == 0 ? start : candidate[f - 1].Position);
            if (!candidate[f].Valid || cMoved < MovementOutcome.PositionTolerance) return true;
        }
        return false;
    }

    /// <summary>cos 10°, written out so no platform's cosine decides a verdict.</summary>
    private const float CosDirectionTolerance = 0.98480775f;

    /// <summary>Whether the two walks' last horizontal moves part by more than <see cref="DirectionToleranceDegrees"/> (never when either never moved).</summary>
    private static bool Turned(Vector3 start, IReadOnlyList<MovementFrame> reference, IReadOnlyList<MovementFrame> candidate) =>
        LastMove(start, reference) is { } a && LastMove(start, candidate) is { } b && a.X * b.X + a.Y * b.Y < CosDirectionTolerance;

    private static Vector2? LastMove(Vector3 start, IReadOnlyList<MovementFrame> frames)
    {
        for (var f = frames.Count - 1; f >= 0; f--)
        {
            var d = frames[f].Position - (f == 0 ? start : frames[f - 1].Position);
            var flat = new Vector2(d.X, d.Y);
            var length = flat.Length();
            if (length >= MovementOutcome.PositionTolerance) return flat / length;
        }
        return null;
    }
}
