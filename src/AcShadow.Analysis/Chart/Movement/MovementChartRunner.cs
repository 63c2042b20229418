using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Movement;
using AcShadow.Fixtures.Movement;

namespace AcShadow.Analysis.Chart.Movement;

/// <summary>
/// Charts one object by movement (movement.md §4): its movement cases (<see cref="ObjectWalks"/>), then every model
/// walked over them in chart order (the reference first), each walk judged against the reference's.
/// </summary>
internal static class MovementChartRunner
{
    public static ObjectMovementChart Chart(ChartSubject subject, MovementChartOptions options, IReadOnlyList<IShapeModel> models,
        ITransitionTimer timer, CancellationToken cancellation = default)
    {
        var walks = ObjectWalks.Lay(subject, options, models[0], cancellation);
        var keep = options.Walk is { } walkId ? walks.Cases.Select(c => c.Id).ToList().IndexOf(walkId) : -1;
        var results = new List<ModelMovement>(models.Count);
        var kept = new List<IReadOnlyList<MovementFrame>>();
        var outlines = new List<ModelOutline>(models.Count);
        foreach (var model in models)
        {
            cancellation.ThrowIfCancellationRequested();
            var closed = ModelPreparation.Prepare(model, walks.Subject);
            results.Add(walks.Walk(model, timer, keep, out var frames, closed));
            outlines.Add(ModelOutline.Of(closed, MovementSubject.Origin));
            if (frames is not null) kept.Add(frames);
        }
        return new ObjectMovementChart(subject.Setup.Id, walks.Cases, results, outlines,
            MovementSubject.Origin + walks.Footprint.Min, MovementSubject.Origin + walks.Footprint.Max)
        {
            Walk = keep >= 0 ? (keep, kept) : null,
        };
    }
}
