using AcShadow.Core.Batch;
using AcShadow.Core.Export;

namespace AcShadow.Analysis.Audit;

/// <summary>An audit's result: the rows shown (filtered and sorted), how many were audited, the skipped ids, the summary, the columns to write.</summary>
public sealed record AuditReport(IReadOnlyList<AuditRow> Rows, int Audited, IReadOnlyList<SkippedItem> Skipped, AuditSummary Summary,
    IReadOnlyList<AuditColumn> Columns);
