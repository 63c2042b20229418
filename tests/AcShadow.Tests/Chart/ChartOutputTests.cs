using System.Globalization;
using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Analysis.Chart.Output;
using AcShadow.Core.Formats;

namespace AcShadow.Tests.Chart;

/// <summary>Chart files are pure functions of the run: the same bytes every time, in every culture.</summary>
public class ChartOutputTests
{
    [Fact]
    public void Same_input_gives_byte_identical_files_in_any_culture()
    {
        var first = Render(CultureInfo.InvariantCulture, 0x020019FF, 0x02001000);
        var second = Render(new CultureInfo("de-DE"), 0x020019FF, 0x02001000);
        var third = Render(new CultureInfo("ar-SA"), 0x020019FF, 0x02001000);
        Assert.Equal(first.Select(f => f.RelativePath), second.Select(f => f.RelativePath));
        for (var i = 0; i < first.Count; i++)
        {
            Assert.Equal(first[i].Content.ToArray(), second[i].Content.ToArray());
            Assert.Equal(first[i].Content.ToArray(), third[i].Content.ToArray());
        }
        Assert.Equal(["chart.csv", "summary.csv", "failures.csv", "speed-accuracy.svg", "failure-map-0x020019FF.svg", "failure-map-0x02001000.svg"],
            first.Select(f => f.RelativePath));
    }

    [Fact]
    public void Csv_files_have_their_headers_and_one_row_per_object_and_model()
    {
        var report = SampleChart.Run(null, 0x020019FF, 0x02001000, 0x02002000);
        var files = report.Files.ToDictionary(f => f.RelativePath, f => System.Text.Encoding.UTF8.GetString(f.Content.Span));
        var chart = files["chart.csv"].Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(ChartCsv.Header, chart[0]);
        Assert.Equal(3 * ShapeModels.All.Count, chart.Length - 1);
        Assert.All(chart.Skip(1), row => Assert.Equal(ChartCsv.Header.Split(',').Length, row.Split(',').Length));
        var summary = files["summary.csv"].Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(SummaryCsv.Header, summary[0]);
        Assert.Equal(ShapeModels.All.Select(m => m.Name), summary.Skip(1).Select(r => r.Split(',')[0]));
        Assert.StartsWith("retail,3,", summary[1]);
        Assert.All(files.Where(f => f.Key.EndsWith(".svg")), f => Assert.StartsWith("<svg xmlns=\"http://www.w3.org/2000/svg\"", f.Value));
    }

    [Theory]
    [InlineData(95.0, "retail")]   // within 15 % of retail: the same cost, the reference wins the tie
    [InlineData(50.0, "union")]    // clearly cheaper: union
    public void Cheapest_exact_model_ignores_timing_noise(double unionNs, string expected)
    {
        var timer = new TableTimer(new Dictionary<string, double>
        {
            ["retail"] = 100, ["union"] = unionNs, ["fallback-cylinder"] = 5, ["spheres"] = 5, ["part-spheres"] = 10, ["part-boxes"] = 8, ["part-hulls"] = 9, ["placement-pose"] = 100,
        });
        // The L-shaped block without placement frames: union poses it as retail does, and nothing cheaper is exact.
        var report = SampleChart.Run([SampleChart.Subjects.Value.For(0x02003300)!], new ChartOptions(), timer: timer);
        Assert.Equal(expected, report.Objects.Single().CheapestExact);
    }

    private sealed class TableTimer(IReadOnlyDictionary<string, double> ns) : IQueryTimer
    {
        public TimingStats Measure(string modelName, PreparedModel model, IReadOnlyList<Probe> probes, ChartOptions options) =>
            TimingStats.Of([ns[modelName]]);
    }

    [Fact]
    public void Every_object_names_a_cheapest_exact_model_that_is_exact_and_fastest_among_exact_ones()
    {
        var report = SampleChart.Run(null, 0x020019FF, 0x02001000, 0x02002000, 0x02003000);
        foreach (var o in report.Objects)
        {
            var cheapest = o.Models.Single(m => m.Model == o.CheapestExact);
            Assert.True(cheapest.Exact);
            var fastest = o.Models.Where(m => m.Exact).Min(m => m.Timing.MedianNs);
            Assert.True(cheapest.Timing.MedianNs <= fastest * ChartRunner.CostTieFactor);
        }
        // A creature has no BSP: retail tests its CylSpheres, which cheaper primitive models reproduce on every probe.
        Assert.Contains(report.Objects.Single(o => o.SetupId == 0x02001000).CheapestExact, new[] { "fallback-cylinder", "spheres" });
        Assert.True(report.Objects.Single(o => o.SetupId == 0x02001000).Models.Single(m => m.Model == "spheres").Exact);
    }

    private static IReadOnlyList<OutputFile> Render(CultureInfo culture, params uint[] setups)
    {
        var saved = (CultureInfo.CurrentCulture, CultureInfo.CurrentUICulture);
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.CurrentUICulture = culture;
            return SampleChart.Run(null, setups).Files;
        }
        finally
        {
            (CultureInfo.CurrentCulture, CultureInfo.CurrentUICulture) = saved;
        }
    }
}
