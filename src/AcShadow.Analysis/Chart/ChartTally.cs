namespace AcShadow.Analysis.Chart;

/// <summary>
/// The per-model totals of a chart, added object by object, so a run over a whole dat keeps only these
/// (counts, each object's timed batches) and not every object's probes and answers.
/// </summary>
public sealed class ChartTally(IReadOnlyList<string> models)
{
    private readonly Totals[] _totals = models.Select(_ => new Totals()).ToArray();

    public IReadOnlyList<string> Models { get; } = models;
    public int Objects { get; private set; }

    /// <summary>The movement chart's totals (objects charted by movement only).</summary>
    public Movement.MovementTally Movement { get; } = new(models);

    public void Add(ObjectChart chart)
    {
        Objects++;
        if (chart.Movement is { } movement) Movement.Add(movement);
        for (var m = 0; m < _totals.Length; m++)
        {
            var o = chart.Models[m];
            var t = _totals[m];
            t.Probes += o.Probes;
            t.Agree += o.Agree;
            t.FalsePass += o.FalsePass;
            t.FalseBlock += o.FalseBlock;
            t.DoorwayProbes += o.DoorwayProbes;
            t.DoorwayFalsePass += o.DoorwayFalsePass;
            t.DoorwayFalseBlock += o.DoorwayFalseBlock;
            if (o.Exact) t.ExactObjects++;
            t.Min = Math.Min(t.Min, o.AgreementPercent);
            t.Max = Math.Max(t.Max, o.AgreementPercent);
            t.BatchNs.AddRange(o.Timing.BatchNs);
            if (chart.CheapestExact == Models[m]) t.CheapestExact++;
        }
    }

    public IReadOnlyList<ModelSummary> Summaries() => Models.Select((name, m) =>
    {
        var t = _totals[m];
        return new ModelSummary(name, Objects, t.Probes, t.Agree, t.FalsePass, t.FalseBlock,
            t.DoorwayProbes, t.DoorwayFalsePass, t.DoorwayFalseBlock, t.ExactObjects,
            Objects == 0 ? double.NaN : t.Min, Objects == 0 ? double.NaN : t.Max,
            TimingStats.Of(t.BatchNs.ToArray()), t.CheapestExact);
    }).ToArray();

    private sealed class Totals
    {
        public long Probes, Agree, FalsePass, FalseBlock, DoorwayProbes, DoorwayFalsePass, DoorwayFalseBlock;
        public int ExactObjects, CheapestExact;
        public double Min = double.PositiveInfinity, Max = double.NegativeInfinity;
        public List<double> BatchNs { get; } = [];
    }
}
