namespace AcShadow.Bench.Harness;

/// <summary>Compares two output folders file by file (names and bytes).</summary>
public static class OutputComparison
{
    /// <summary>At most a few differences, described; empty when the folders match (ignoring <paramref name="ignore"/>).</summary>
    public static IReadOnlyList<string> Differences(string a, string b, IReadOnlyCollection<string> ignore)
    {
        var left = Files(a, ignore);
        var right = Files(b, ignore);
        var problems = new List<string>();
        problems.AddRange(left.Except(right).Take(5).Select(f => $"only in {a}: {f}"));
        problems.AddRange(right.Except(left).Take(5).Select(f => $"only in {b}: {f}"));
        foreach (var f in left.Intersect(right))
        {
            if (problems.Count >= 10) break;
            if (!File.ReadAllBytes(Path.Combine(a, f)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(b, f)))) problems.Add($"differs: {f}");
        }
        return problems;
    }

    private static SortedSet<string> Files(string dir, IReadOnlyCollection<string> ignore) =>
        new(Directory.GetFiles(dir, "*", SearchOption.AllDirectories)
            .Select(f => Path.GetRelativePath(dir, f).Replace('\\', '/'))
            .Where(f => !ignore.Contains(f)), StringComparer.Ordinal);
}
