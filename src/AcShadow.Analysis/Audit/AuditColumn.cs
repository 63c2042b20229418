using System.Globalization;
using AcShadow.Core.Json;

namespace AcShadow.Analysis.Audit;

/// <summary>
/// One audit column: its key (CSV/JSON name and --sort field), its table header, and its value.
/// Values are int, float, double, bool, string, string lists, or null (not applicable).
/// </summary>
public sealed record AuditColumn(string Key, string Header, Func<AuditRow, object?> Value, string Description)
{
    /// <summary>Text for tables and CSV: invariant culture, floats in shortest round-trip form, null as <paramref name="none"/>.</summary>
    public string Text(AuditRow row, string none) => Value(row) switch
    {
        null => none,
        bool b => b ? "yes" : "no",
        int i => i.ToString(CultureInfo.InvariantCulture),
        float f => f == 0f ? "0" : f.ToString("R", CultureInfo.InvariantCulture),
        double d => d == 0d ? "0" : d.ToString("R", CultureInfo.InvariantCulture),
        IEnumerable<string> list => string.Join(' ', list),
        var other => other.ToString() ?? none,
    };

    public JsonNode Json(AuditRow row) => Value(row) switch
    {
        null => JsonNull.Value,
        bool b => b ? JsonBool.True : JsonBool.False,
        int i => JsonNum.Of(i),
        float f => JsonNum.Of(f),
        double d => JsonNum.Of(d),
        IEnumerable<string> list => JsonArr.Of(list),
        var other => new JsonStr(other.ToString() ?? ""),
    };
}
