using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Collision;

/// <summary>
/// Collects diagnostics, listing at most <see cref="PerCode"/> of each code and then one line saying how
/// many more there were, so a 300-polygon building with a systematic problem stays readable.
/// </summary>
internal sealed class DiagnosticLog
{
    public const int PerCode = 12;

    private readonly List<Diagnostic> _listed = [];
    private readonly Dictionary<string, int> _counts = new(StringComparer.Ordinal);
    private readonly List<string> _codeOrder = [];

    public void Add(string code, string message)
    {
        var count = _counts.GetValueOrDefault(code);
        if (count == 0) _codeOrder.Add(code);
        _counts[code] = count + 1;
        if (count < PerCode) _listed.Add(new Diagnostic(code, message));
    }

    public IReadOnlyList<Diagnostic> ToList()
    {
        var all = new List<Diagnostic>(_listed);
        foreach (var code in _codeOrder)
        {
            var extra = _counts[code] - PerCode;
            if (extra > 0) all.Add(new Diagnostic(CollisionDiagnosticCodes.Truncated, $"{extra} more {code} diagnostic(s) not listed"));
        }
        return all;
    }
}
