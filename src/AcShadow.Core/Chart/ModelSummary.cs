namespace AcShadow.Core.Chart;

/// <summary>One model over every object of a report (see Output/SummaryCsv for what each figure pools).</summary>
public sealed record ModelSummary(
    string Model, int Objects, long Probes, long Agree, long FalsePass, long FalseBlock,
    long DoorwayProbes, long DoorwayFalsePass, long DoorwayFalseBlock, int ExactObjects,
    double MinObjectAgreement, double MaxObjectAgreement, TimingStats Timing, int CheapestExactObjects)
{
    public double AgreementPercent => Probes == 0 ? 100.0 : 100.0 * Agree / Probes;

    public static IReadOnlyList<ModelSummary> All(ChartReport report) => report.Models.Select((name, m) =>
    {
        var outcomes = report.Objects.Select(o => o.Models[m]).ToArray();
        return new ModelSummary(
            name, outcomes.Length,
            outcomes.Sum(o => (long)o.Probes), outcomes.Sum(o => (long)o.Agree),
            outcomes.Sum(o => (long)o.FalsePass), outcomes.Sum(o => (long)o.FalseBlock),
            outcomes.Sum(o => (long)o.DoorwayProbes), outcomes.Sum(o => (long)o.DoorwayFalsePass), outcomes.Sum(o => (long)o.DoorwayFalseBlock),
            outcomes.Count(o => o.Exact),
            outcomes.Length == 0 ? double.NaN : outcomes.Min(o => o.AgreementPercent),
            outcomes.Length == 0 ? double.NaN : outcomes.Max(o => o.AgreementPercent),
            TimingStats.Of(outcomes.SelectMany(o => o.Timing.BatchNs).ToArray()),
            report.Objects.Count(o => o.CheapestExact == name));
    }).ToArray();
}
