using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;

namespace AcShadow.Tests.Chart;

/// <summary>A timer that measures nothing: fixed nanoseconds per model, so chart files are byte-comparable.</summary>
internal sealed class FixedTimer : IQueryTimer
{
    public static readonly IReadOnlyDictionary<string, double> Default = new Dictionary<string, double>
    {
        ["retail"] = 400, ["union"] = 420, ["fallback-cylinder"] = 40, ["spheres"] = 45, ["part-spheres"] = 60, ["placement-pose"] = 410,
    };

    public TimingStats Measure(string modelName, PreparedModel model, IReadOnlyList<Probe> probes, ChartOptions options)
    {
        var ns = Default.GetValueOrDefault(modelName, 100);
        return TimingStats.Of([ns * 0.9, ns, ns * 1.2]);
    }
}
