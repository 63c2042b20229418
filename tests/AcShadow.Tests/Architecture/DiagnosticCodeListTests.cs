using System.Reflection;
using System.Text.RegularExpressions;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// docs/errors.md, "Diagnostic codes": every code is a named constant of a class named *DiagnosticCodes in the
/// assemblies acshadow ships, and the table lists exactly those (code and class), each row's test existing.
/// </summary>
public sealed partial class DiagnosticCodeListTests
{
    private static readonly Lazy<IReadOnlyList<DocumentedCode>> Documented = new(ReadTable);

    /// <summary>The CLI and every acshadow assembly it loads.</summary>
    private static IReadOnlyList<Assembly> Shipped()
    {
        var found = new SortedDictionary<string, Assembly>(StringComparer.Ordinal);
        var pending = new Stack<Assembly>([typeof(AcShadow.Cli.AcShadowApp).Assembly]);
        while (pending.TryPop(out var assembly))
        {
            if (!found.TryAdd(assembly.GetName().Name!, assembly)) continue;
            foreach (var reference in assembly.GetReferencedAssemblies().Where(r => r.Name!.StartsWith("AcShadow.", StringComparison.Ordinal)))
                pending.Push(Assembly.Load(reference));
        }
        return [.. found.Values];
    }

    /// <summary>(class, code) of every const string of every class named *DiagnosticCodes, public or not.</summary>
    private static IReadOnlyList<(string Class, string Code)> Defined() =>
        [.. Shipped().SelectMany(a => a.GetTypes())
            .Where(t => t.Name.EndsWith("DiagnosticCodes", StringComparison.Ordinal))
            .SelectMany(t => t.GetFields(BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static)
                .Where(f => f.IsLiteral && f.FieldType == typeof(string))
                .Select(f => (t.Name, (string)f.GetRawConstantValue()!)))];

    private sealed record DocumentedCode(string Class, string Code, string Test);

    private static IReadOnlyList<DocumentedCode> ReadTable()
    {
        var text = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "docs", "errors.md"));
        var start = text.IndexOf("\n## Diagnostic codes\n", StringComparison.Ordinal);
        Assert.True(start >= 0, "docs/errors.md has no \"## Diagnostic codes\" section");
        var end = text.IndexOf("\n## ", start + 1, StringComparison.Ordinal);
        var section = end < 0 ? text[start..] : text[start..end];
        return [.. Row().Matches(section).Select(m => new DocumentedCode(m.Groups["class"].Value, m.Groups["code"].Value, m.Groups["test"].Value.Trim()))];
    }

    [GeneratedRegex(@"^\| `(?<code>[a-z0-9-]+)` \| `(?<class>\w+)` \([A-Za-z]+\) \|[^|\n]*\|[^|\n]*\|(?<test>[^|\n]*)\|$", RegexOptions.Multiline)]
    private static partial Regex Row();

    [Fact]
    public void Every_code_a_class_defines_is_listed_in_docs_errors_md_with_its_class()
    {
        var documented = Documented.Value.Select(d => (d.Class, d.Code)).ToHashSet();
        var defined = Defined();
        Assert.NotEmpty(defined);
        var missing = defined.Where(d => !documented.Contains(d)).Select(d => $"{d.Class}: {d.Code}").ToArray();
        Assert.True(missing.Length == 0, $"docs/errors.md \"Diagnostic codes\" does not list: {string.Join(", ", missing)}");
    }

    [Fact]
    public void Every_code_docs_errors_md_lists_is_defined_by_the_class_it_names()
    {
        var defined = Defined().ToHashSet();
        Assert.NotEmpty(Documented.Value);
        var stale = Documented.Value.Where(d => !defined.Contains((d.Class, d.Code))).Select(d => $"{d.Class}: {d.Code}").ToArray();
        Assert.True(stale.Length == 0, $"docs/errors.md \"Diagnostic codes\" lists codes no *DiagnosticCodes class defines: {string.Join(", ", stale)}");
    }

    [Fact]
    public void Every_test_the_table_names_exists()
    {
        var tests = typeof(DiagnosticCodeListTests).Assembly.GetTypes();
        var named = Documented.Value.Select(d => d.Test).Where(t => t.StartsWith('`')).Distinct().ToArray();
        Assert.NotEmpty(named);
        var absent = named.Where(cell =>
        {
            var name = cell.Trim('`');
            name = name[(name.LastIndexOf('/') + 1)..];
            var dot = name.IndexOf('.', StringComparison.Ordinal);
            var (type, method) = (name[..dot], name[(dot + 1)..]);
            return !tests.Any(t => t.Name == type && t.GetMethod(method) is not null);
        }).ToArray();
        Assert.True(absent.Length == 0, $"docs/errors.md \"Diagnostic codes\" names tests that do not exist: {string.Join(", ", absent)}");
    }
}
