using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Analysis.Chart;

/// <summary>Measures a prepared model's time per query over probes. Swappable so tests get fixed numbers.</summary>
internal interface IQueryTimer
{
    TimingStats Measure(string modelName, PreparedModel model, IReadOnlyList<Probe> probes, ChartOptions options);
}
