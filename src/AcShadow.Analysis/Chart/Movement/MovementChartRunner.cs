using System.Numerics;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Movement;
using AcShadow.Core.Poses;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Movement;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// Charts one object by movement (movement.md §4): the movement cases `acshadow move` would write for it (laid
/// out on the closed reference, each run by the movement reference against the retail shapes, with its
/// fragility), then every model, prepared in each door state and run as the client's primitives
/// (<see cref="ModelObstacles"/>), over the same walks, each walk judged against the reference's
/// (<see cref="MovementJudge"/>). Cases and models run one after another, so the answers are the same on any machine.
/// </summary>
internal static class MovementChartRunner
{
    public static ObjectMovementChart Chart(ChartSubject subject, MovementChartOptions options, IReadOnlyList<IShapeModel> models,
        ITransitionTimer timer, CancellationToken cancellation = default)
    {
        var mover = options.Mover;
        var isDoor = options.IsDoor(subject.Setup.Id);
        DoorState[] states = isDoor ? [DoorState.Closed, DoorState.Open] : [DoorState.Closed];
        var prepared = new PreparedModel[states.Length][];
        var obstacles = new IReadOnlyList<MovementObject>[states.Length][];
        var references = new MovementObject[states.Length];
        var ethereal = new bool[states.Length];
        var names = new string[states.Length];
        for (var s = 0; s < states.Length; s++)
        {
            var inState = subject with { Pose = (subject.Pose ?? new ShapeBuildOptions(ShapePolicy.Retail)) with { DoorState = states[s] } };
            var retail = inState.Build(inState.Options(ShapePolicy.Retail));
            ethereal[s] = retail.Pose.Ethereal;
            names[s] = !isDoor ? "default" : states[s] == DoorState.Open ? "open" : "closed";
            references[s] = Whole(retail.Shapes, inState, ethereal[s]);
            prepared[s] = [.. models.Select(m => ModelPreparation.Prepare(m, inState))];
            obstacles[s] = [.. prepared[s].Select(p => ModelObstacles.Of(p, ethereal[s]))];
        }

        // The gate and the walks are laid out on the closed (resting) reference, so every state shares them.
        var footprint = MovementFootprint.Of(references[0]);
        var plans = new List<(MovementCasePlan Plan, int State)>();
        for (var s = 0; s < states.Length; s++)
            plans.AddRange((isDoor ? MovementCasePlanner.Door(footprint, mover, names[s]) : MovementCasePlanner.Object(footprint, mover, names[s])).Select(p => (p, s)));
        var cases = new MovementCase[plans.Count];
        for (var i = 0; i < plans.Count; i++)
        {
            cancellation.ThrowIfCancellationRequested();
            cases[i] = MovementSuiteBuilder.Run(plans[i].Plan, mover, references[plans[i].State]);
        }

        var walkCase = options.Walk is { } walkId ? Array.FindIndex(cases, c => c.Id == walkId) : -1;
        var walkFrames = new List<IReadOnlyList<MovementFrame>>();
        var results = new List<ModelMovement>(models.Count);
        for (var m = 0; m < models.Count; m++)
        {
            cancellation.ThrowIfCancellationRequested();
            var frames = new IReadOnlyList<MovementFrame>[cases.Length];
            var ns = timer.NsPerTransition(models[m].Name, () =>
            {
                long transitions = 0;
                for (var i = 0; i < cases.Length; i++)
                {
                    frames[i] = MovementReference.Run(mover, obstacles[plans[i].State][m], cases[i].Walk);
                    transitions += frames[i].Count;
                }
                return transitions;
            });
            var verdicts = new MovementVerdict[cases.Length];
            var ends = new Vector3[cases.Length];
            var diverging = new int?[cases.Length];
            for (var i = 0; i < cases.Length; i++)
            {
                var s = plans[i].State;
                var retail = prepared[s][0];
                Func<Vector3, float, bool>? occupied = ethereal[s] ? null : (c, r) => retail.Overlaps(c - MovementSubject.Origin, r);
                verdicts[i] = MovementJudge.Judge(cases[i], frames[i], mover, occupied);
                ends[i] = MovementJudge.End(cases[i].Walk, frames[i]);
                diverging[i] = MovementJudge.FirstDivergingFrame(cases[i].Expected, frames[i]);
            }
            if (walkCase >= 0) walkFrames.Add(frames[walkCase]);
            results.Add(new ModelMovement(models[m].Name, prepared[0][m].Shapes.Count, verdicts, ends, diverging, frames.Sum(f => (long)f.Count), ns));
        }
        var outlines = prepared[0].Select(p => ModelOutline.Of(p, MovementSubject.Origin)).ToArray();
        return new ObjectMovementChart(subject.Setup.Id, cases, results, outlines, MovementSubject.Origin + footprint.Min, MovementSubject.Origin + footprint.Max)
        {
            Walk = walkCase >= 0 ? (walkCase, walkFrames) : null,
        };
    }

    /// <summary>The retail shapes as the one object the movement cases walk against (as MovementSubject builds it).</summary>
    private static MovementObject Whole(IReadOnlyList<ShadowShape> shapes, ChartSubject subject, bool ethereal)
    {
        var bsps = new Dictionary<uint, CompiledBsp>();
        foreach (var shape in shapes)
            if (shape.CollisionType == CollisionType.Bsp && shape.GfxObjId is { } id && !bsps.ContainsKey(id) && subject.Bsps(id) is { } bsp)
                bsps[id] = bsp;
        return new MovementObject(shapes, bsps, MovementSubject.Origin, Quaternion.Identity, 1f, ethereal);
    }
}
