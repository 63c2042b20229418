namespace AcShadow.Analysis.Chart.Movement;

/// <summary>The per-model totals of a movement chart, added object by object, so a run keeps only these and not every walk.</summary>
public sealed class MovementTally(IReadOnlyList<string> models)
{
    private readonly Totals[] _totals = models.Select(_ => new Totals()).ToArray();

    public IReadOnlyList<string> Models { get; } = models;
    public int Objects { get; private set; }

    public void Add(ObjectMovementChart chart)
    {
        Objects++;
        for (var m = 0; m < _totals.Length; m++)
        {
            var model = chart.Models[m];
            var t = _totals[m];
            t.Cases += chart.Cases.Count;
            foreach (var verdict in MovementVerdicts.All) t.Counts[(int)verdict] += model.Count(verdict, chart.Fragile);
            t.FragileCases += chart.Fragile.Count(f => f);
            t.FragileFalsePass += model.FragileCount(MovementVerdict.FalsePass, chart.Fragile);
            if (model.FalsePasses > 0) t.FalsePassObjects++;
            if (double.IsFinite(model.NsPerTransition))
            {
                t.Transitions += model.Transitions;
                t.Ns += model.NsPerTransition * model.Transitions;
            }
        }
    }

    public IReadOnlyList<MovementSummary> Summaries() => Models.Select((name, m) =>
    {
        var t = _totals[m];
        return new MovementSummary(name, Objects, t.Cases, [.. t.Counts], t.FragileCases, t.FragileFalsePass, t.FalsePassObjects,
            t.Transitions, t.Transitions == 0 ? double.NaN : t.Ns / t.Transitions);
    }).ToArray();

    private sealed class Totals
    {
        public long Cases, FragileCases, FragileFalsePass, Transitions;
        public int FalsePassObjects;
        public double Ns;
        public long[] Counts { get; } = new long[MovementVerdicts.All.Length];
    }
}
