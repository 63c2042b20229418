using System.Text;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>chart.csv: one row per object × model, in selection order then model order.</summary>
public static class ChartCsv
{
    public const string Header =
        "setup,model,shapes,probes,doorway_probes,agree,agreement_pct,false_pass,false_block,doorway_false_pass,doorway_false_block," +
        "median_ns_per_query,p10_ns_per_query,p90_ns_per_query,exact,cheapest_exact,grid_spacing_m,diagnostics," +
        "face_probes,edge_probes,vertex_probes,plane_probes,stability_false_pass,stability_false_block";

    /// <summary>One object's rows (one per model), each ending in a newline.</summary>
    public static string Rows(ObjectChart o)
    {
        var csv = new StringBuilder();
        var kinds = ProbeKinds.Stability.Select(k => I(ChartProbes.Count(o.Probes, k))).ToArray();
        foreach (var m in o.Models)
        {
            int stabilityPass = 0, stabilityBlock = 0;
            for (var i = 0; i < o.Probes.Count; i++)
            {
                if (!ProbeKinds.IsStability(o.Probes[i].Kind) || m.Answers[i] == o.Reference[i]) continue;
                if (o.Reference[i]) stabilityPass++; else stabilityBlock++;
            }
            csv.Append(string.Join(',',
                Id(o.SetupId), Csv(m.Model), I(m.ShapeCount), I(m.Probes), I(m.DoorwayProbes), I(m.Agree), F(m.AgreementPercent, 3),
                I(m.FalsePass), I(m.FalseBlock), I(m.DoorwayFalsePass), I(m.DoorwayFalseBlock),
                F(m.Timing.MedianNs, 1), F(m.Timing.P10Ns, 1), F(m.Timing.P90Ns, 1),
                m.Exact ? "yes" : "no", m.Model == o.CheapestExact ? "yes" : "no", F(o.GridSpacing, 3), I(m.Diagnostics.Count),
                string.Join(',', kinds), I(stabilityPass), I(stabilityBlock)));
            csv.Append('\n');
        }
        return csv.ToString();
    }
}
