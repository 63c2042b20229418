using System.Text;
using AcShadow.Analysis.Compile;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Formats;
using static AcShadow.Analysis.Chart.Output.ChartFormat;

namespace AcShadow.Analysis.Chart.Cells;

/// <summary>
/// cells.csv: one row per indoor cell a landblock chart probed, in cell id order: its structure, its
/// probes by kind, how many its retail tree blocks and lets through, and the time per query of that tree.
/// </summary>
internal static class CellsCsv
{
    public const string FileName = "cells.csv";

    public const string Header =
        "cell,environment,cell_structure,polygons,model,probes,grid_probes,face_probes,edge_probes,vertex_probes,plane_probes," +
        "blocked,clear,median_ns_per_query,p10_ns_per_query,p90_ns_per_query,diagnostics";

    /// <summary>The file's start (its header row), for the chart's check that it replaces only its own files.</summary>
    public static OutputFile Head => OutputFile.Text(FileName, Header + "\n");

    public static string Write(IEnumerable<CellChart> cells)
    {
        var csv = new StringBuilder(Header).Append('\n');
        foreach (var c in cells)
        {
            var counts = ProbeCounts.Of(c.Cell.Probes);
            var blocked = c.Blocked;
            csv.Append(string.Join(',',
                Id(c.Cell.Cell.Id), Id(c.Cell.Cell.EnvironmentFileId), I(c.Cell.Cell.CellStructure), I(c.Cell.Bsp?.Polygons.Length ?? 0),
                c.Cell.Bsp is null ? ObjectCompilation.UnresolvedLabel : CellChart.Model, I(counts.Total), I(counts.Of(ProbeKind.Grid)),
                I(counts.Of(ProbeKind.Face)), I(counts.Of(ProbeKind.Edge)), I(counts.Of(ProbeKind.Vertex)), I(counts.Of(ProbeKind.SplittingPlane)),
                I(blocked), I(c.Answers.Length - blocked), F(c.Timing.MedianNs, 1), F(c.Timing.P10Ns, 1), F(c.Timing.P90Ns, 1), I(c.Cell.Diagnostics.Count)));
            csv.Append('\n');
        }
        return csv.ToString();
    }
}
