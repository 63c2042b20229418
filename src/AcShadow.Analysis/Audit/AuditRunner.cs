using AcShadow.Analysis.Chart;
using AcShadow.Analysis.Chart.Models;
using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Binary;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Export;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// Audits every Setup of a plan (in parallel, results in plan order), optionally charts each one with the
/// collision chart (one after another, so the chart's timings are not disturbed), then filters and sorts.
/// </summary>
public static class AuditRunner
{
    public static AuditReport Run(IDatSource dat, BatchPlan plan, AuditQuery query, int jobs,
        ChartOptions? chart = null, Action<BatchProgress>? progress = null, Core.Shapes.ShapeBuildOptions? pose = null)
    {
        var rows = new AuditRow?[plan.Setups.Count];
        var problems = new string?[plan.Setups.Count];
        Parallel.For(0, plan.Setups.Count, new ParallelOptions { MaxDegreeOfParallelism = jobs }, i =>
        {
            try
            {
                Setup? setup = dat.ReadSetup(plan.Setups[i].Id);
                if (setup is null) problems[i] = SkippedItem.NotInDat;
                else rows[i] = AuditRowBuilder.Build(setup, dat.ReadGfxObj, 1f, dat, pose);
            }
            catch (DatFormatException e)
            {
                problems[i] = $"unreadable: {e.Message}";
            }
        });
        if (chart is not null) AddChart(dat, rows, chart, progress);

        var skipped = plan.Skipped.ToList();
        for (var i = 0; i < problems.Length; i++)
            if (problems[i] is { } p) skipped.Add(new SkippedItem(plan.Setups[i].Id, p, plan.Setups[i].From));
        var audited = rows.OfType<AuditRow>().ToArray();
        var shown = query.Apply(audited);
        var sortedSkipped = skipped.OrderBy(s => s.Id).ToArray();
        return new AuditReport(shown, audited.Length, sortedSkipped, AuditSummary.Of(shown, sortedSkipped.Length),
            chart is null ? AuditColumns.All : AuditColumns.WithChart);
    }

    private static void AddChart(IDatSource dat, AuditRow?[] rows, ChartOptions options, Action<BatchProgress>? progress)
    {
        var subjects = new ChartSubjects(dat);
        var timer = new StopwatchQueryTimer();
        var total = rows.Count(r => r is not null);
        var done = 0;
        for (var i = 0; i < rows.Length; i++)
        {
            if (rows[i] is not { } row || subjects.For(row.SetupId) is not { } subject) continue;
            var chart = ChartRunner.Chart(subject, options, ShapeModels.All, timer);
            var exact = chart.Models.Where(m => m.Exact).Select(m => m.Model).ToArray();
            rows[i] = row with { Chart = new ChartVerdict(exact, chart.CheapestExact.Length == 0 ? null : chart.CheapestExact) };
            progress?.Invoke(new BatchProgress(++done, total));
        }
    }
}
