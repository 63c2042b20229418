using AcShadow.Forge;
using AcShadow.Core.Dat;
using AcShadow.Core.Movement;
using AcShadow.Core.Poses;
using AcShadow.Fixtures.Movement;
using AcShadow.Forging;
using BenchmarkDotNet.Attributes;

namespace AcShadow.Bench;

/// <summary>
/// The movement reference's transitions per second (target: at most 20 µs a transition on one core): the
/// sample door's whole suite (616 walks, closed and open), and 100 Setups of the scale dat, every 20th,
/// each walked from the 16 compass headings at walking speed, aimed at its centre. One operation is one transition
/// (one frame of one walk); the fragility reruns are not counted here (they run each case six more times).
/// </summary>
[ShortRunJob]
public class MovementBenchmarks
{
    private (Mover Mover, MovementObject Object, Walk Walk)[] _door = [];
    private (Mover Mover, MovementObject Object, Walk Walk)[] _scale = [];

    public const int DoorTransitions = 17_732;
    public const int ScaleTransitions = 148_912;

    [GlobalSetup]
    public void Setup()
    {
        var (portal, _) = SampleDats.Build();
        using (var sample = DatDatabase.Open(new MemoryStream(portal), "sample"))
        {
            var mover = MoverSetup.Read(sample, SampleSpecAuthor.MoverSetup)!;
            _door = [.. Walks(sample, SampleSpecAuthor.DoorSetup, mover, door: true)];
        }
        using var scale = ScaleDat.Open();
        var human = MoverSetup.Read(scale, scale.ListIds(DatObjectKind.Setup).First(id => scale.ReadSetup(id)!.Spheres.Count >= 2))
            ?? throw new InvalidOperationException("the scale dat has no two-sphere Setup");
        var ids = scale.ListIds(DatObjectKind.Setup).Where((_, i) => i % 20 == 0).Take(100);
        _scale = [.. ids.SelectMany(id => Walks(scale, id, human, door: false)
            .Where(w => w.Walk.Velocity.Length() < MovementCasePlanner.RunSpeed - 1f)
            .Where((_, i) => i % 7 == 0))];
        Require(_door, DoorTransitions);
        Require(_scale, ScaleTransitions);
    }

    /// <summary>The operation counts are constants (BenchmarkDotNet needs them at compile time): a change to the sets must update them.</summary>
    private static void Require((Mover, MovementObject, Walk Walk)[] walks, int transitions)
    {
        var actual = walks.Sum(w => w.Walk.Frames);
        if (actual != transitions) throw new InvalidOperationException($"the walks hold {actual} transitions, not {transitions}: update the constant");
    }

    private static IEnumerable<(Mover Mover, MovementObject Object, Walk Walk)> Walks(IDatSource dat, uint id, Mover mover, bool door)
    {
        var subject = MovementSubject.Read(dat, id)!;
        var footprint = MovementFootprint.Of(subject.Build(dat, DoorState.Closed).Object);
        foreach (var state in door ? new[] { DoorState.Closed, DoorState.Open } : [DoorState.Closed])
        {
            var (obj, _) = subject.Build(dat, state);
            var plans = door ? MovementCasePlanner.Door(footprint, mover, "s") : MovementCasePlanner.Object(footprint, mover, "s");
            foreach (var plan in plans) yield return (mover, obj, plan.Walk);
        }
    }

    [Benchmark(OperationsPerInvoke = DoorTransitions)]
    public int SampleDoorSuite() => Run(_door);

    [Benchmark(OperationsPerInvoke = ScaleTransitions)]
    public int ScaleSetups() => Run(_scale);

    private static int Run((Mover Mover, MovementObject Object, Walk Walk)[] walks)
    {
        var valid = 0;
        foreach (var (mover, obj, walk) in walks)
            foreach (var frame in MovementReference.Run(mover, obj, walk))
                if (frame.Valid) valid++;
        return valid;
    }
}
