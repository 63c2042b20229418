namespace AcShadow.Analysis.Chart;

/// <summary>One model over every object of a run (<see cref="ChartTally"/>; see Output/SummaryCsv for what each figure pools).</summary>
public sealed record ModelSummary(
    string Model, int Objects, long Probes, long Agree, long FalsePass, long FalseBlock,
    long DoorwayProbes, long DoorwayFalsePass, long DoorwayFalseBlock, int ExactObjects,
    double MinObjectAgreement, double MaxObjectAgreement, TimingStats Timing, int CheapestExactObjects)
{
    public double AgreementPercent => Probes == 0 ? 100.0 : 100.0 * Agree / Probes;
}
