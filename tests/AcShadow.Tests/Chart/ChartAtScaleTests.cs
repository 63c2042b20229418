using System.Numerics;
using AcShadow.Cli.Terminal;
using AcShadow.Core.Batch;
using AcShadow.Core.Chart;
using AcShadow.Core.Chart.Output;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Chart;

/// <summary>
/// docs/chart.md, "charting a whole dat" and docs/errors.md, "absurd inputs": results stream out object by
/// object in order (whatever --jobs), the probe grid stays bounded however large the object, absurd
/// scales are refused, and long id lists are summarised.
/// </summary>
public class ChartAtScaleTests
{
    private static readonly uint[] Setups = [0x020019FF, 0x02001000, 0x02002000];

    [Fact]
    public void Streamed_charts_arrive_in_order_one_by_one_and_match_the_whole_report_with_any_job_count()
    {
        var whole = SampleChart.Run(null, Setups);
        foreach (var jobs in new[] { 1, 2, 3 })
        {
            var arrived = new List<(uint Id, int DoneBefore)>();
            var done = 0;
            var rows = new System.Text.StringBuilder();
            var tally = ChartRunner.Stream(Setups.Length, i => SampleChart.Subjects.Value.For(Setups[i]), new ChartOptions(), chart =>
            {
                arrived.Add((chart.SetupId, done));
                rows.Append(ChartCsv.Rows(chart));
            }, timer: new FixedTimer(), progress: (d, _) => done = d, jobs: jobs);

            Assert.Equal(Setups, arrived.Select(a => a.Id));
            // Each object is handed over before the next is counted done: nothing waits for the end.
            Assert.Equal([0, 1, 2], arrived.Select(a => a.DoneBefore));
            Assert.Equal(ChartCsv.Write(whole), ChartCsv.Header + "\n" + rows);
            Assert.Equal(SummaryCsv.Write(whole), SummaryCsv.Write(tally.Summaries()));
        }
    }

    [Fact]
    public void The_grid_stays_under_its_probe_limit_however_large_the_object()
    {
        var options = new ChartOptions();
        var huge = new Bounds(new Vector3(-1e30f), new Vector3(1e30f));
        var grid = ProbeGrid.Build(huge, options);
        Assert.InRange(grid.Probes.Count, 1, options.MaxGridProbes);
        Assert.True(grid.Spacing > options.Spacing);
    }

    [Theory]
    [InlineData("1e30")]
    [InlineData("1e5")]
    [InlineData("1e-45")]
    public void Absurd_scales_are_refused_with_a_usage_error(string scale)
    {
        using var dir = new TempDir();
        var run = CliRun.Of("chart", "--setup", "0x020019FF", "--scale", scale, "--out", dir.Path, "--quiet");
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--scale: {scale} is outside 0.001-1000", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
        Assert.Empty(dir.Files());
    }

    [Fact]
    public void Plain_progress_lines_name_the_command_that_runs()
    {
        var error = new StringWriter();
        var progress = new ProgressReporter(error, isTerminal: false, quiet: false, "objects charted", "chart");
        Thread.Sleep(TimeSpan.FromSeconds(2.2)); // plain lines come every 2 s at most
        progress.Report(new BatchProgress(3, 10));
        Assert.StartsWith("chart: 3/10 objects charted", error.ToString());
    }

    [Fact]
    public void Skipped_ids_are_summarised_not_listed_in_one_enormous_line()
    {
        using var dir = new TempDir();
        var list = Path.Combine(dir.Path, "ids.txt");
        File.WriteAllLines(list, Enumerable.Range(0xF000, 30).Select(i => $"0x0200{i:X4}"));

        var run = CliRun.Of("batch", "--setups", list, "--out", Path.Combine(dir.Path, "out"), "--quiet");

        Assert.Equal(0, run.ExitCode);
        var line = Assert.Single(run.Out.Split('\n'), l => l.Contains("skipped 30"));
        Assert.Contains("0x0200F000", line);
        Assert.Contains("… and 20 more (all in index.json's skipped)", line);
        Assert.DoesNotContain("0x0200F01D", line);
    }
}
