using System.Numerics;

namespace AcShadow.Fixtures.Movement;

/// <summary>
/// What a walk came to, judged from its frames (movement.md §2.3): its class, whether the mover's origin
/// crossed the case's gate plane, the first frame with a collision, and the end's displacement from the
/// start split into progress along the intent, lateral deflection and height change. An engine under test
/// classifies its own frames with <see cref="Of"/> and compares classes.
/// </summary>
/// <param name="Class">
/// fell (no contact at the end), steppedUp / steppedDown (|dz| &gt; 0.02 m on walkable ground), reached (the end
/// within 1e-3 m of start + velocity × quantum × frames), edgeStopped (an edge slide or edge stop held it short),
/// slid (deflected sideways by more than 1e-3 m), blocked (otherwise: held short on its line).
/// </param>
/// <param name="CrossedGate">Some frame ended with the origin on the gate plane's far side.</param>
/// <param name="FirstContactFrame">The first frame with a collision normal or an object hit (null: none).</param>
/// <param name="Progress">The end's displacement from the start along the intent, m.</param>
/// <param name="Lateral">Its displacement across the intent (to the left), m.</param>
/// <param name="Dz">Its height change, m.</param>
public sealed record MovementOutcome(string Class, bool CrossedGate, int? FirstContactFrame, float Progress, float Lateral, float Dz)
{
    public const string Reached = "reached", Blocked = "blocked", Slid = "slid", SteppedUp = "steppedUp",
        SteppedDown = "steppedDown", EdgeStopped = "edgeStopped", Fell = "fell";

    /// <summary>Position tolerance of reached and slid (5ε: movement.md §2.4).</summary>
    public const float PositionTolerance = 1e-3f;

    /// <summary>A height change beyond this on walkable ground is a step.</summary>
    public const float StepTolerance = 0.02f;

    private static readonly HashSet<string> EdgeEvents = ["cliffSlide", "precipiceSlide", "edgeStop"];

    /// <param name="walk">The walk the frames ran.</param>
    /// <param name="frames">Its frames, in order.</param>
    /// <param name="gate">The plane the walk aims across, its normal pointing from the start's side to the far side.</param>
    public static MovementOutcome Of(Walk walk, IReadOnlyList<MovementFrame> frames, Plane gate)
    {
        ArgumentNullException.ThrowIfNull(walk);
        ArgumentNullException.ThrowIfNull(frames);
        var start = walk.Start;
        var end = frames.Count > 0 ? frames[^1].Position : start;
        var flat = new Vector3(walk.Velocity.X, walk.Velocity.Y, 0f);
        var speed = MathF.Sqrt(flat.X * flat.X + flat.Y * flat.Y);
        var along = speed > 0f ? new Vector3(flat.X / speed, flat.Y / speed, 0f) : Vector3.Zero;
        var across = new Vector3(-along.Y, along.X, 0f);
        var moved = end - start;
        var progress = moved.X * along.X + moved.Y * along.Y;
        var lateral = moved.X * across.X + moved.Y * across.Y;
        var dz = moved.Z;
        var travel = walk.Quantum * frames.Count;
        var intended = new Vector3(start.X + flat.X * travel, start.Y + flat.Y * travel, start.Z);
        var crossed = frames.Any(f => Side(gate, f.Position) > 0f);
        int? firstContact = frames.FirstOrDefault(f => f.HitObject || f.CollisionNormal is not null)?.Frame;

        var last = frames.Count > 0 ? frames[^1] : null;
        var missed = end - intended;
        var @class = last is { Contact: false } ? Fell
            : MathF.Abs(dz) > StepTolerance && last is { OnWalkable: true } ? (dz > 0f ? SteppedUp : SteppedDown)
            : MathF.Sqrt(missed.X * missed.X + missed.Y * missed.Y + missed.Z * missed.Z) <= PositionTolerance ? Reached
            : frames.Any(f => f.Events.Any(EdgeEvents.Contains)) ? EdgeStopped
            : MathF.Abs(lateral) > PositionTolerance ? Slid
            : Blocked;
        return new MovementOutcome(@class, crossed, firstContact, progress, lateral, dz);
    }

    private static float Side(Plane gate, Vector3 p) => gate.Normal.X * p.X + gate.Normal.Y * p.Y + gate.Normal.Z * p.Z + gate.D;
}
