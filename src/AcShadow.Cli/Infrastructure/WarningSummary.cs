using System.Globalization;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Per-object warnings of a run over many objects: the first <see cref="IdSummary.Shown"/> objects' warnings
/// go to stderr in full as they come, then one line says the rest are counted; <see cref="Summary"/> gives
/// every warning by code for the summary. A whole dat's chart would otherwise print thousands of lines in
/// which an error would be lost. Warnings are "code: message" (a <c>Diagnostic</c>'s code, or a note's
/// text up to its first colon).
/// </summary>
public sealed class WarningSummary(TextWriter err)
{
    private readonly SortedDictionary<string, int> _byCode = new(StringComparer.Ordinal);
    private int _objects;

    /// <summary>One object's diagnostics and notes (notes are already "code: message").</summary>
    public void Add(string subject, IEnumerable<Diagnostic> diagnostics, IEnumerable<string>? notes = null) =>
        Add(subject, [.. diagnostics.Select(d => $"{d.Code}: {d.Message}"), .. notes ?? []]);

    private void Add(string subject, IReadOnlyCollection<string> warnings)
    {
        if (warnings.Count == 0) return;
        lock (_byCode)
        {
            _objects++;
            foreach (var warning in warnings)
            {
                var colon = warning.IndexOf(':', StringComparison.Ordinal);
                var code = colon > 0 ? warning[..colon] : "note";
                _byCode[code] = _byCode.GetValueOrDefault(code) + 1;
                if (_objects <= IdSummary.Shown) err.WriteLine($"warning: {subject}: {warning}");
            }
            if (_objects == IdSummary.Shown + 1)
                err.WriteLine($"warning: more objects have warnings; only the first {IdSummary.Shown} objects' are shown, and the summary counts them all by code");
        }
    }

    /// <summary>
    /// "N warning(s) in M object(s): code count, ... (where they were printed)", codes most frequent first,
    /// then by code; null when there were none.
    /// </summary>
    public string? Summary()
    {
        lock (_byCode)
        {
            if (_objects == 0) return null;
            var total = _byCode.Values.Sum();
            var codes = _byCode.OrderByDescending(c => c.Value).ThenBy(c => c.Key, StringComparer.Ordinal)
                .Select(c => string.Create(CultureInfo.InvariantCulture, $"{c.Key} {c.Value}"));
            var shown = _objects > IdSummary.Shown ? $"the first {IdSummary.Shown} objects' in full on stderr" : "in full on stderr";
            return string.Create(CultureInfo.InvariantCulture, $"{total} warning(s) in {_objects} object(s): {string.Join(", ", codes)} ({shown})");
        }
    }
}
