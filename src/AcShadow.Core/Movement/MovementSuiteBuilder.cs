using System.Numerics;
using AcShadow.Core.Dat;
using AcShadow.Core.Poses;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Movement;

/// <summary>A generated suite and what its file records beside the cases: each state's pose, the footprint, the BSPs.</summary>
public sealed record GeneratedSuite(MovementSuite Suite, IReadOnlyDictionary<string, PoseProvenance> Poses, MovementFootprint Footprint, MovementSubject Subject);

/// <summary>
/// Generates one object Setup's movement suite: the object in each requested state, the mover, the planned
/// cases (door or other object, <see cref="MovementCasePlanner"/>), each run through the movement reference,
/// classified, and rerun perturbed to mark it fragile. Cases run in parallel into fixed slots, so the suite
/// is the same whatever the thread count.
/// </summary>
public static class MovementSuiteBuilder
{
    /// <summary>How far a case's start and speed are moved to test it for fragility (movement.md §2.4).</summary>
    public const float Perturbation = 1e-5f;

    private static readonly float[] Signs = [1f, -1f];

    /// <param name="states">Null: a door's closed and open states, or the one retail pose ("default") of any other object.</param>
    public static GeneratedSuite Build(IDatSource dat, uint setupId, uint moverSetupId, Mover mover, bool isDoor,
        IReadOnlyList<DoorState>? states, int jobs, CancellationToken cancel = default)
    {
        ArgumentNullException.ThrowIfNull(dat);
        ArgumentNullException.ThrowIfNull(mover);
        var subject = MovementSubject.Read(dat, setupId) ?? throw new ArgumentException($"no Setup {setupId:X8} in the dat", nameof(setupId));
        var chosen = states ?? (isDoor ? [DoorState.Closed, DoorState.Open] : [DoorState.Closed]);
        var objects = new Dictionary<string, MovementObject>();
        var poses = new Dictionary<string, PoseProvenance>();
        var plans = new List<MovementCasePlan>();
        // The gate and the walks are laid out on the closed (resting) door, so both states share them.
        var closed = subject.Build(dat, DoorState.Closed);
        var footprint = MovementFootprint.Of(closed.Object);
        foreach (var state in chosen)
        {
            var name = !isDoor ? "default" : state == DoorState.Open ? "open" : "closed";
            var (obj, set) = state == DoorState.Closed ? closed : subject.Build(dat, state);
            objects[name] = obj;
            poses[name] = set.Pose;
            plans.AddRange(isDoor ? MovementCasePlanner.Door(footprint, mover, name) : MovementCasePlanner.Object(footprint, mover, name));
        }
        var cases = new MovementCase[plans.Count];
        Parallel.For(0, plans.Count, new ParallelOptions { MaxDegreeOfParallelism = Math.Max(1, jobs), CancellationToken = cancel },
            i => cases[i] = Run(plans[i], mover, objects[plans[i].State]));
        return new GeneratedSuite(new MovementSuite(setupId, moverSetupId, mover, objects, cases), poses, footprint, subject);
    }

    /// <summary>One case: the reference run, its outcome, and its stability against the perturbed reruns.</summary>
    public static MovementCase Run(MovementCasePlan plan, Mover mover, MovementObject obj)
    {
        var walk = plan.Walk;
        var frames = MovementReference.Run(mover, obj, walk);
        var outcome = MovementOutcome.Of(walk, frames, plan.Gate);
        var margin = float.PositiveInfinity;
        foreach (var f in frames) margin = MathF.Min(margin, f.MinMargin);
        var fragile = margin < Perturbation;
        foreach (var perturbed in Perturbed(walk))
        {
            if (fragile) break;
            fragile = MovementOutcome.Of(perturbed, MovementReference.Run(mover, obj, perturbed), plan.Gate).Class != outcome.Class;
        }
        return new MovementCase(plan.Id, plan.State, plan.Heading, walk, plan.Gate, frames, outcome, fragile, margin);
    }

    /// <summary>The start moved ±1e-5 m along x and along y, and the velocity scaled by 1 ± 1e-5.</summary>
    private static IEnumerable<Walk> Perturbed(Walk walk)
    {
        foreach (var sign in Signs)
        {
            yield return walk with { Start = walk.Start + new Vector3(sign * Perturbation, 0f, 0f) };
            yield return walk with { Start = walk.Start + new Vector3(0f, sign * Perturbation, 0f) };
            yield return walk with { Velocity = walk.Velocity * (1f + sign * Perturbation) };
        }
    }
}
