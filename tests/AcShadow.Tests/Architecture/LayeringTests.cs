using System.Reflection;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// One way down. The assemblies stack (each references only assemblies listed before it), and inside each
/// assembly its namespaces stack the same way, read from the compiled code (<see cref="NamespaceGraph"/>):
/// the dat is read into domain records, the records are shaped, writers write them, and what runs a whole
/// export or analysis sits on top; nothing below knows what is built on it. A new namespace needs its place
/// in <see cref="Orders"/>.
/// </summary>
public sealed class LayeringTests
{
    /// <summary>The tool's assemblies, lowest first: Fixtures &lt;- Core &lt;- Analysis &lt;- the CLI.</summary>
    private static readonly Assembly[] Assemblies =
    [
        typeof(AcShadow.Files.AtomicFile).Assembly,
        typeof(AcShadow.Fixtures.FixtureSet).Assembly,
        typeof(AcShadow.Core.Dat.DatArchive).Assembly,
        typeof(AcShadow.Forging.SampleDats).Assembly,
        typeof(AcShadow.Analysis.Chart.ChartOptions).Assembly,
        typeof(AcShadow.Cli.AcShadowApp).Assembly,
    ];

    /// <summary>Each assembly's root namespace and its namespaces, lowest first ("" is the root itself).</summary>
    private static readonly Dictionary<string, Layers> Orders = new()
    {
        ["AcShadow.Files"] = Layers.Of("AcShadow.Files", ""),
        ["AcShadow.Fixtures"] = Layers.Of("AcShadow.Fixtures",
            "Geometry", "Json", "Shapes", "Bsp", "Collision", "Movement", "Scenes", "Cells", "Formats", "Batch", ""),
        ["AcShadow.Core"] = Layers.Of("AcShadow.Core",
            "Json", "Dat.Binary", "Dat.Objects", "Dat", "Catalog", "Poses", "Shapes", "Bsp", "Movement", "Formats", "Export",
            "Scenes", "Cells", "Batch", "Verify"),
        ["AcShadow.Forging"] = Layers.Of("AcShadow.Forging", "Spec", "Geometry", "Bsp", ""),
        ["AcShadow.Analysis"] = Layers.Of("AcShadow.Analysis",
            "Reports", "Fitting", "Chart.Models", "Chart.Movement", "Chart", "Chart.Output", "Compile", "Chart.Cells", "Audit", "Doctor", "View"),
        ["acshadow"] = Layers.Of("AcShadow.Cli", "Infrastructure", "Conventions", "Terminal", "Output", "Commands", ""),
    };

    public static TheoryData<string> Layered() => [.. Orders.Keys];

    [Theory]
    [MemberData(nameof(Layered))]
    public void Every_namespace_uses_only_namespaces_below_it(string assembly)
    {
        var order = Orders[assembly].Namespaces;
        var graph = Graph(assembly);
        var problems = new List<string>();
        problems.AddRange(graph.Namespaces.Except(order).Select(n => $"{n} has no place in the order: add it where it belongs"));
        problems.AddRange(order.Except(graph.Namespaces).Select(n => $"{n} is in the order but declares no type: remove it"));
        foreach (var from in graph.Namespaces.Intersect(order))
            foreach (var (to, uses) in graph.Uses(from))
            {
                var upward = Array.IndexOf(order, to) > Array.IndexOf(order, from);
                if (upward)
                    problems.Add($"{from} -> {to}, which is above it: {Example(uses)}");
            }

        Assert.True(problems.Count == 0, $"{assembly}:\n" + string.Join("\n", problems));
    }

    /// <summary>
    /// The compiler copies a constant into the code that uses it, so a use of nothing but a constant leaves
    /// no trace in the assembly: the source's <c>using</c> directives are held to the same order.
    /// </summary>
    [Theory]
    [MemberData(nameof(Layered))]
    public void No_source_file_imports_a_namespace_above_its_own(string assembly)
    {
        var layers = Orders[assembly];
        var order = layers.Namespaces;
        var project = Path.Combine(RepositoryRoot.Path, "src", layers.Root);
        var upward = new List<string>();
        var files = 0;
        foreach (var file in Directory.EnumerateFiles(project, "*.cs", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
        {
            var relative = Path.GetRelativePath(project, file).Replace('\\', '/');
            if (relative.StartsWith("obj/", StringComparison.Ordinal) || relative.StartsWith("bin/", StringComparison.Ordinal)) continue;
            files++;
            var lines = File.ReadAllLines(file);
            var own = lines.Select(l => UsingOrNamespace("namespace ", l)).FirstOrDefault(n => n is not null);
            if (own is null || !order.Contains(own)) continue;
            foreach (var imported in lines.Select(l => UsingOrNamespace("using static ", l) ?? UsingOrNamespace("using ", l)).OfType<string>())
            {
                var target = order.Where(n => imported == n || imported.StartsWith(n + ".", StringComparison.Ordinal)).MaxBy(n => n.Length);
                if (target is not null && Array.IndexOf(order, target) > Array.IndexOf(order, own))
                    upward.Add($"{relative} ({own}) imports {imported}, which is above it");
            }
        }

        Assert.True(files > 0, $"{project} has no source files");
        Assert.True(upward.Count == 0, $"{assembly}:\n" + string.Join("\n", upward));
    }

    private static string? UsingOrNamespace(string keyword, string line) =>
        line.StartsWith(keyword, StringComparison.Ordinal) && line.TrimEnd().EndsWith(';') && !line.Contains('=', StringComparison.Ordinal)
            ? line[keyword.Length..].TrimEnd().TrimEnd(';').Trim()
            : null;

    [Theory]
    [MemberData(nameof(Layered))]
    public void No_namespaces_use_each_other_in_a_cycle(string assembly)
    {
        var graph = Graph(assembly);
        var cycles = Cycles(graph).Select(cycle =>
            string.Join(" -> ", cycle) + " -> " + cycle[0] + "\n    " +
            string.Join("\n    ", cycle.Select((from, i) => Example(graph.Uses(from)[cycle[(i + 1) % cycle.Count]]))));
        Assert.True(!cycles.Any(), $"{assembly} has namespace cycles:\n" + string.Join("\n", cycles));
    }

    [Fact]
    public void Each_assembly_references_only_assemblies_below_it()
    {
        var names = Assemblies.Select(a => a.GetName().Name!).ToArray();
        var upward = new List<string>();
        for (var i = 0; i < Assemblies.Length; i++)
        {
            var graph = NamespaceGraph.Read(Assemblies[i].Location, Orders[names[i]].Root);
            upward.AddRange(graph.AssemblyReferences.Where(r => Array.IndexOf(names, r) >= i).Select(r => $"{names[i]} references {r}"));
        }

        Assert.True(upward.Count == 0, string.Join("\n", upward));
    }

    [Fact]
    public void The_export_project_does_not_name_the_layers_above_it()
    {
        var project = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "src", "AcShadow.Core", "AcShadow.Core.csproj"));
        Assert.DoesNotContain("AcShadow.Analysis", project, StringComparison.Ordinal);
        Assert.DoesNotContain("AcShadow.Cli", project, StringComparison.Ordinal);
    }

    /// <summary>The graph's cycles, one per strongly connected group of namespaces.</summary>
    internal static IReadOnlyList<IReadOnlyList<string>> Cycles(NamespaceGraph graph)
    {
        IEnumerable<string> Next(string from) =>
            graph.Uses(from).Keys.Where(graph.Namespaces.Contains);

        // Tarjan's strongly connected components; each group of two or more holds a cycle.
        var index = new Dictionary<string, int>(StringComparer.Ordinal);
        var low = new Dictionary<string, int>(StringComparer.Ordinal);
        var stack = new Stack<string>();
        var groups = new List<HashSet<string>>();
        void Visit(string v)
        {
            index[v] = low[v] = index.Count;
            stack.Push(v);
            foreach (var w in Next(v))
            {
                if (!index.ContainsKey(w))
                {
                    Visit(w);
                    low[v] = Math.Min(low[v], low[w]);
                }
                else if (stack.Contains(w))
                {
                    low[v] = Math.Min(low[v], index[w]);
                }
            }

            if (low[v] != index[v]) return;
            var group = new HashSet<string>(StringComparer.Ordinal);
            string w2;
            do group.Add(w2 = stack.Pop());
            while (w2 != v);
            if (group.Count > 1) groups.Add(group);
        }

        foreach (var n in graph.Namespaces.Where(n => !index.ContainsKey(n))) Visit(n);

        // One concrete cycle per group: the shortest way back to its first namespace.
        return groups.Select(group =>
        {
            var start = group.Min(StringComparer.Ordinal)!;
            var previous = new Dictionary<string, string>(StringComparer.Ordinal);
            var queue = new Queue<string>([start]);
            while (queue.Count > 0)
            {
                var v = queue.Dequeue();
                foreach (var w in Next(v).Where(group.Contains))
                {
                    if (w == start)
                    {
                        var path = new List<string> { v };
                        while (path[^1] != start) path.Add(previous[path[^1]]);
                        path.Reverse();
                        return (IReadOnlyList<string>)path;
                    }

                    if (previous.TryAdd(w, v)) queue.Enqueue(w);
                }
            }

            return [.. group.Order(StringComparer.Ordinal)];
        }).ToArray();
    }

    private static string Example(SortedSet<string> uses) =>
        uses.Count == 1 ? uses.Min! : $"{uses.Min} (and {uses.Count - 1} more)";

    private static NamespaceGraph Graph(string assemblyName)
    {
        var assembly = Assemblies.Single(a => a.GetName().Name == assemblyName);
        return NamespaceGraph.Read(assembly.Location, Orders[assemblyName].Root);
    }

    /// <summary>An assembly's root namespace and its namespaces (folders under the root), lowest first.</summary>
    private sealed record Layers(string Root, string[] Namespaces)
    {
        public static Layers Of(string root, params string[] folders) =>
            new(root, [.. folders.Select(f => f.Length == 0 ? root : root + "." + f)]);
    }
}
