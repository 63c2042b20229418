using System.Text;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// summary.csv: one row per model over the whole selection. Counts and agreement pool every probe of every
/// object; min/max object agreement is the spread over objects; the time columns are the median, p10 and
/// p90 of all timed batches of all objects pooled.
/// </summary>
public static class SummaryCsv
{
    public const string Header =
        "model,objects,probes,agree,agreement_pct,false_pass,false_block,doorway_probes,doorway_false_pass,doorway_false_block," +
        "exact_objects,min_object_agreement_pct,max_object_agreement_pct,median_ns_per_query,p10_ns_per_query,p90_ns_per_query,cheapest_exact_objects";


    public static string Write(IReadOnlyList<ModelSummary> summaries)
    {
        var csv = new StringBuilder(Header).Append('\n');
        foreach (var s in summaries)
        {
            csv.Append(string.Join(',',
                Csv(s.Model), I(s.Objects), I(s.Probes), I(s.Agree), F(s.AgreementPercent, 3), I(s.FalsePass), I(s.FalseBlock),
                I(s.DoorwayProbes), I(s.DoorwayFalsePass), I(s.DoorwayFalseBlock), I(s.ExactObjects),
                F(s.MinObjectAgreement, 3), F(s.MaxObjectAgreement, 3), F(s.Timing.MedianNs, 1), F(s.Timing.P10Ns, 1), F(s.Timing.P90Ns, 1),
                I(s.CheapestExactObjects)));
            csv.Append('\n');
        }
        return csv.ToString();
    }
}
