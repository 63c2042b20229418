using System.Text;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Output;

/// <summary>
/// failures.csv: per object and model, the disagreeing probes nearest the boundary (rank 1 = nearest), so
/// a reader sees where a model fails, not only how often. Gaps are <see cref="BoundaryGap"/> in metres.
/// </summary>
public static class FailuresCsv
{
    public const string Header = "setup,model,rank,failure,kind,line,offset_m,x,y,z,radius,gap_to_reference_m,gap_to_model_m";

    /// <summary>One object's rows, each ending in a newline.</summary>
    public static string Rows(ObjectChart o)
    {
        var csv = new StringBuilder();
        foreach (var m in o.Models)
            for (var rank = 0; rank < m.Nearest.Count; rank++)
            {
                var d = m.Nearest[rank];
                var p = d.Probe;
                csv.Append(string.Join(',',
                    Id(o.SetupId), Csv(m.Model), I(rank + 1), d.FalsePass ? "false_pass" : "false_block",
                    ProbeKinds.Name(p.Kind), p.Kind == ProbeKind.Doorway ? I(p.Line) : "",
                    p.Kind == ProbeKind.Doorway ? F(p.Offset, 4) : "",
                    F(p.Center.X, 4), F(p.Center.Y, 4), F(p.Center.Z, 4), F(p.Radius, 4),
                    F(d.GapToReference, 4), F(d.GapToModel, 4)));
                csv.Append('\n');
            }
        return csv.ToString();
    }
}
