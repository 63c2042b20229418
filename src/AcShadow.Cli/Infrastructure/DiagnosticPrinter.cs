using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Cli.Infrastructure;

/// <summary>Diagnostics go to stderr, one line each, prefixed with the object they concern.</summary>
public static class DiagnosticPrinter
{
    public static void Print(TextWriter err, string subject, IEnumerable<Diagnostic> diagnostics)
    {
        foreach (var d in diagnostics) err.WriteLine($"warning: {subject}: {d.Code}: {d.Message}");
    }
}
