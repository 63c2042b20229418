namespace AcShadow.Analysis.Audit;

/// <summary>
/// Which rows an audit shows and in what order. <see cref="Sort"/> is a column key, "-key" for
/// descending; rows without a value sort last; ties go by Setup id. <see cref="PoseDiffers"/> keeps only
/// the Setups whose retail and placement poses differ.
/// </summary>
public sealed record AuditQuery(bool OnlyBsp = false, bool FlagMismatch = false, double? MaxCoverage = null, string Sort = "id")
{
    public bool PoseDiffers { get; init; }

    public bool Keeps(AuditRow row) =>
        (!OnlyBsp || row.PartsHavePhysicsBsp)
        && (!PoseDiffers || row.PoseDiffers)
        && (!FlagMismatch || row.FlagMismatch)
        && (MaxCoverage is not { } max || row.Coverage is { } c && c <= max);

    public IReadOnlyList<AuditRow> Apply(IEnumerable<AuditRow> rows)
    {
        var descending = Sort.StartsWith('-');
        var column = AuditColumns.Find(Sort.TrimStart('-', '+'))
            ?? throw new ArgumentException($"unknown sort field '{Sort}': use one of {string.Join(", ", AuditColumns.WithChart.Select(c => c.Key))}");
        var kept = rows.Where(Keeps).ToList();
        kept.Sort((a, b) =>
        {
            var order = CompareValues(column.Value(a), column.Value(b));
            if (descending && order != 0 && column.Value(a) is not null && column.Value(b) is not null) order = -order;
            return order != 0 ? order : a.SetupId.CompareTo(b.SetupId);
        });
        return kept;
    }

    private static int CompareValues(object? a, object? b) => (a, b) switch
    {
        (null, null) => 0,
        (null, _) => 1,
        (_, null) => -1,
        (int x, int y) => x.CompareTo(y),
        (float x, float y) => x.CompareTo(y),
        (double x, double y) => x.CompareTo(y),
        (bool x, bool y) => x.CompareTo(y),
        (string x, string y) => string.CompareOrdinal(x, y),
        (IEnumerable<string> x, IEnumerable<string> y) => string.CompareOrdinal(string.Join(' ', x), string.Join(' ', y)),
        _ => 0,
    };
}
