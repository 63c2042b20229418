using System.Text;
using AcShadow.Analysis.Chart.Movement;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// movement-summary.csv: one row per model over every object charted by movement: the verdict counts over the
/// non-fragile cases, the fragile cases and their false passes, how many objects the model false-passed on,
/// its agreement (agree over non-fragile cases) and, last, its time per transition pooled over all walks (a measurement).
/// </summary>
public static class MovementSummaryCsv
{
    public static readonly string Header =
        "model,objects,cases," + string.Join(',', MovementVerdicts.All.Select(MovementVerdicts.Name)) +
        ",fragile_cases,fragile_false_pass,false_pass_objects,agreement_pct,transitions,ns_per_transition";

    public static string Write(IReadOnlyList<MovementSummary> summaries)
    {
        var csv = new StringBuilder(Header).Append('\n');
        foreach (var s in summaries)
        {
            csv.Append(string.Join(',',
                Csv(s.Model), I(s.Objects), I(s.Cases), string.Join(',', s.Counts.Select(c => I(c))),
                I(s.FragileCases), I(s.FragileFalsePass), I(s.FalsePassObjects), F(s.AgreementPercent, 3),
                I(s.Transitions), F(s.NsPerTransition, 0)));
            csv.Append('\n');
        }
        return csv.ToString();
    }
}
