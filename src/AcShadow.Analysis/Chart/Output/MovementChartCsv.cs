using System.Text;
using AcShadow.Analysis.Chart.Movement;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// movement-chart.csv: one row per object × model, in selection order then model order. Verdict counts are over
/// the non-fragile cases; fragile cases are counted apart, with their false passes (never tolerated). The first
/// diverging frame is the earliest frame of any case where the model's walk parts from the reference's, with
/// that case's id; end errors are the distances between the two walks' ends over every case (median and p90,
/// nearest rank). The last column is a measurement (it varies run to run); every other column is the same on
/// every run and at any --jobs.
/// </summary>
public static class MovementChartCsv
{
    public static readonly string Header =
        "setup,model,shapes,cases," + string.Join(',', MovementVerdicts.All.Select(MovementVerdicts.Name)) +
        ",fragile_cases,fragile_false_pass,first_diverging_frame,first_diverging_case,median_end_error_m,p90_end_error_m,transitions,ns_per_transition";

    public static string Rows(ObjectMovementChart chart)
    {
        var csv = new StringBuilder();
        foreach (var m in chart.Models)
        {
            int? first = null;
            var firstCase = "";
            for (var i = 0; i < chart.Cases.Count; i++)
                if (m.FirstDivergingFrames[i] is { } f && (first is null || f < first))
                {
                    first = f;
                    firstCase = chart.Cases[i].Id;
                }
            var errors = chart.Cases.Select((c, i) => (double)System.Numerics.Vector3.Distance(m.Ends[i], MovementJudge.End(c.Walk, c.Expected)))
                .Order().ToArray();
            csv.Append(string.Join(',',
                Id(chart.SetupId), Csv(m.Model), I(m.Shapes), I(chart.Cases.Count),
                string.Join(',', MovementVerdicts.All.Select(v => I(m.Count(v, chart.Fragile)))),
                I(chart.Fragile.Count(f => f)), I(m.FragileCount(MovementVerdict.FalsePass, chart.Fragile)),
                first is { } ff ? I(ff) : "", Csv(firstCase),
                F(TimingStats.Percentile(errors, 0.5), 4), F(TimingStats.Percentile(errors, 0.9), 4),
                I(m.Transitions), F(m.NsPerTransition, 0)));
            csv.Append('\n');
        }
        return csv.ToString();
    }
}
