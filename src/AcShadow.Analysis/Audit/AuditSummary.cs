namespace AcShadow.Analysis.Audit;

/// <summary>Counts per category over the rows an audit shows (the block printed after the rows).</summary>
public sealed record AuditSummary(IReadOnlyList<(string Key, string Label, int Count)> Counts)
{
    public const double LowCoverage = 0.1;
    public const double HalfCoverage = 0.5;

    public static AuditSummary Of(IReadOnlyList<AuditRow> rows, int skipped)
    {
        var bsp = rows.Where(r => r.Category == AuditCategory.Bsp).ToArray();
        return new AuditSummary(
        [
            ("setups", "Setups", rows.Count),
            ("bsp", "family bsp (parts' PhysicsBSPs)", bsp.Length),
            ("cylinders", "family cylinders (CylSpheres)", rows.Count(r => r.Category == AuditCategory.Cylinders)),
            ("spheres", "family spheres (Spheres)", rows.Count(r => r.Category == AuditCategory.Spheres)),
            ("none", "family none (nothing collides)", rows.Count(r => r.Category == AuditCategory.None)),
            ("flagMismatch", "HasPhysicsBSP flag disagrees with the parts", rows.Count(r => r.FlagMismatch)),
            ("missingParts", "with a part missing from the dat", rows.Count(r => r.MissingParts > 0)),
            ("noPose", "with a BSP part left unposed (no-pose)", rows.Count(r => r.DiagnosticCodes.Contains(Fixtures.Shapes.DiagnosticCodes.NoPose))),
            ("policiesDiffer", "retail and union build different shapes or placements",
                rows.Count(r => r.RetailShapes != r.UnionShapes || r.Placement != r.UnionPlacement)),
            ("coverageBelow10", "bsp, cylinder fallback covers < 10% of the footprint", bsp.Count(r => r.Coverage < LowCoverage)),
            ("coverage10To50", "bsp, covers 10% to < 50%", bsp.Count(r => r.Coverage >= LowCoverage && r.Coverage < HalfCoverage)),
            ("coverageAtLeast50", "bsp, covers ≥ 50%", bsp.Count(r => r.Coverage >= HalfCoverage)),
            ("coverageUnknown", "bsp, no measurable footprint", bsp.Count(r => r.Coverage is null)),
            ("skipped", "skipped (not in the dat or unreadable)", skipped),
        ]);
    }

    public int this[string key] => Counts.First(c => c.Key == key).Count;
}
