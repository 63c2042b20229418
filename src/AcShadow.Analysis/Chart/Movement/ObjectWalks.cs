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
/// One object's movement cases, ready to walk any model through (movement.md §4): the cases `acshadow move` would
/// write for it (laid out on the closed reference, each run by the movement reference against the retail shapes,
/// with its fragility), the object's door states and, per state, the reference model prepared (its placement
/// query decides whether a walk stood where retail's geometry is). <see cref="Walk"/> prepares a model in each
/// state, runs it as the client's primitives (<see cref="ModelObstacles"/>) over the same walks and judges each
/// against the reference's (<see cref="MovementJudge"/>). Everything runs in order, so the answers are the same on any machine.
/// </summary>
internal sealed class ObjectWalks
{
    private readonly ChartSubject[] _subjects;
    private readonly bool[] _ethereal;
    private readonly PreparedModel[] _reference;
    private readonly int[] _stateOf;
    private readonly Mover _mover;

    public IReadOnlyList<MovementCase> Cases { get; }
    public MovementFootprint Footprint { get; }

    /// <summary>The object in its first state (closed, or its one pose), as <see cref="Walk"/> prepares models for it.</summary>
    public ChartSubject Subject => _subjects[0];

    private ObjectWalks(ChartSubject[] subjects, bool[] ethereal, PreparedModel[] reference, int[] stateOf, Mover mover,
        IReadOnlyList<MovementCase> cases, MovementFootprint footprint)
    {
        _subjects = subjects;
        _ethereal = ethereal;
        _reference = reference;
        _stateOf = stateOf;
        _mover = mover;
        Cases = cases;
        Footprint = footprint;
    }

    /// <param name="reference">The model the cases' expected walks are checked against for placement (retail).</param>
    public static ObjectWalks Lay(ChartSubject subject, MovementChartOptions options, IShapeModel reference, CancellationToken cancellation = default)
    {
        var mover = options.Mover;
        var isDoor = options.IsDoor(subject.Setup.Id);
        DoorState[] states = isDoor ? [DoorState.Closed, DoorState.Open] : [DoorState.Closed];
        var subjects = new ChartSubject[states.Length];
        var ethereal = new bool[states.Length];
        var prepared = new PreparedModel[states.Length];
        var objects = new MovementObject[states.Length];
        var names = new string[states.Length];
        for (var s = 0; s < states.Length; s++)
        {
            subjects[s] = subject with { Pose = (subject.Pose ?? new ShapeBuildOptions(ShapePolicy.Retail)) with { DoorState = states[s] } };
            var retail = subjects[s].Build(subjects[s].Options(ShapePolicy.Retail));
            ethereal[s] = retail.Pose.Ethereal;
            names[s] = !isDoor ? "default" : states[s] == DoorState.Open ? "open" : "closed";
            objects[s] = Whole(retail.Shapes, subjects[s], ethereal[s]);
            prepared[s] = ModelPreparation.Prepare(reference, subjects[s]);
        }
        // The gate and the walks are laid out on the closed (resting) reference, so every state shares them.
        var footprint = MovementFootprint.Of(objects[0]);
        var plans = new List<(MovementCasePlan Plan, int State)>();
        for (var s = 0; s < states.Length; s++)
            plans.AddRange((isDoor ? MovementCasePlanner.Door(footprint, mover, names[s]) : MovementCasePlanner.Object(footprint, mover, names[s])).Select(p => (p, s)));
        var cases = new MovementCase[plans.Count];
        for (var i = 0; i < plans.Count; i++)
        {
            cancellation.ThrowIfCancellationRequested();
            cases[i] = MovementSuiteBuilder.Run(plans[i].Plan, mover, objects[plans[i].State]);
        }
        return new ObjectWalks(subjects, ethereal, prepared, [.. plans.Select(p => p.State)], mover, cases, footprint);
    }

    /// <summary>
    /// Walks <paramref name="model"/> over every case and judges each walk, timed by <paramref name="timer"/> (null: untimed); <paramref name="keep"/> (a case index, or −1) gets
    /// its frames kept in <paramref name="kept"/>. <paramref name="prepared"/>: the model already prepared for the closed
    /// (first) state, to prepare it once less.
    /// </summary>
    public ModelMovement Walk(IShapeModel model, ITransitionTimer? timer, int keep, out IReadOnlyList<MovementFrame>? kept, PreparedModel? prepared = null)
    {
        var obstacles = new IReadOnlyList<MovementObject>[_subjects.Length];
        var shapes = 0;
        for (var s = 0; s < _subjects.Length; s++)
        {
            var inState = s == 0 && prepared is not null ? prepared : ModelPreparation.Prepare(model, _subjects[s]);
            if (s == 0) shapes = inState.Shapes.Count;
            obstacles[s] = ModelObstacles.Of(inState, _ethereal[s], _subjects[s].Bsps);
        }
        var frames = new IReadOnlyList<MovementFrame>[Cases.Count];
        long RunAll()
        {
            long transitions = 0;
            for (var i = 0; i < Cases.Count; i++)
            {
                frames[i] = MovementReference.Run(_mover, obstacles[_stateOf[i]], Cases[i].Walk);
                transitions += frames[i].Count;
            }
            return transitions;
        }
        var ns = double.NaN;
        if (timer is null) RunAll();
        else ns = timer.NsPerTransition(model.Name, RunAll);
        var verdicts = new MovementVerdict[Cases.Count];
        var ends = new Vector3[Cases.Count];
        var diverging = new int?[Cases.Count];
        for (var i = 0; i < Cases.Count; i++)
        {
            var s = _stateOf[i];
            var reference = _reference[s];
            Func<Vector3, float, bool>? occupied = _ethereal[s] ? null : (c, r) => reference.Overlaps(c - MovementSubject.Origin, r);
            verdicts[i] = MovementJudge.Judge(Cases[i], frames[i], _mover, occupied);
            ends[i] = MovementJudge.End(Cases[i].Walk, frames[i]);
            diverging[i] = MovementJudge.FirstDivergingFrame(Cases[i].Expected, frames[i]);
        }
        kept = keep >= 0 && keep < frames.Length ? frames[keep] : null;
        return new ModelMovement(model.Name, shapes, verdicts, ends, diverging, frames.Sum(f => (long)f.Count), ns);
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
