using AcShadow.Core.Batch;
using AcShadow.Core.Dat;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Audit;

/// <summary>Audits every Setup of a plan (in parallel, results in plan order), then filters and sorts.</summary>
public static class AuditRunner
{
    public static AuditReport Run(IDatSource dat, BatchPlan plan, AuditQuery query, int jobs)
    {
        var rows = new AuditRow?[plan.Setups.Count];
        var problems = new string?[plan.Setups.Count];
        Parallel.For(0, plan.Setups.Count, new ParallelOptions { MaxDegreeOfParallelism = jobs }, i =>
        {
            try
            {
                Setup? setup = dat.ReadSetup(plan.Setups[i].Id);
                if (setup is null) problems[i] = SkippedItem.NotInDat;
                else rows[i] = AuditRowBuilder.Build(setup, dat.ReadGfxObj);
            }
            catch (DatFormatException e)
            {
                problems[i] = $"unreadable: {e.Message}";
            }
        });
        var skipped = plan.Skipped.ToList();
        for (var i = 0; i < problems.Length; i++)
            if (problems[i] is { } p) skipped.Add(new SkippedItem(plan.Setups[i].Id, p, plan.Setups[i].From));
        var audited = rows.OfType<AuditRow>().ToArray();
        var shown = query.Apply(audited);
        var sortedSkipped = skipped.OrderBy(s => s.Id).ToArray();
        return new AuditReport(shown, audited.Length, sortedSkipped, AuditSummary.Of(shown, sortedSkipped.Length));
    }
}
