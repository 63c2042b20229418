using AcShadow.Fixtures;
using AcShadow.Tests.Support;
using PublicApiGenerator;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// The AcShadow.Fixtures package's public API is held in an approved file, so every change to what consumers
/// compile against is a deliberate, reviewed diff (and a version bump in CHANGELOG.md), never a side effect.
/// </summary>
public sealed class PublicApiTests
{
    private const string ApproveVariable = "ACSHADOW_APPROVE_API";

    internal static string ApprovedPath { get; } =
        Path.Combine(RepositoryRoot.Path, "tests", "AcShadow.Tests", "Architecture", "AcShadow.Fixtures.approved.txt");

    [Fact]
    public void The_fixtures_package_public_api_is_the_approved_one()
    {
        var options = new ApiGeneratorOptions { IncludeAssemblyAttributes = false };
        var actual = Normalise(typeof(FixtureSet).Assembly.GeneratePublicApi(options));
        if (Environment.GetEnvironmentVariable(ApproveVariable) == "1")
        {
            File.WriteAllText(ApprovedPath, actual);
            return;
        }

        var approved = File.Exists(ApprovedPath) ? Normalise(File.ReadAllText(ApprovedPath)) : "";
        if (approved == actual) return;

        var a = approved.Split('\n');
        var b = actual.Split('\n');
        var first = 0;
        while (first < a.Length && first < b.Length && a[first] == b[first]) first++;
        Assert.Fail(
            $"the public API of AcShadow.Fixtures changed (first difference at line {first + 1}: approved \"{Line(a, first)}\", now \"{Line(b, first)}\"). " +
            $"If the change is deliberate, approve it with `{ApproveVariable}=1 dotnet test tests/AcShadow.Tests --filter PublicApiTests`, " +
            "review the diff of the approved file, and note it in CHANGELOG.md.");
    }

    [Fact]
    public void The_approved_api_names_only_the_packages_own_namespaces()
    {
        var namespaces = File.ReadAllLines(ApprovedPath)
            .Where(l => l.StartsWith("namespace ", StringComparison.Ordinal))
            .Select(l => l["namespace ".Length..].Trim())
            .ToArray();
        Assert.NotEmpty(namespaces);
        Assert.All(namespaces, n => Assert.True(n == "AcShadow.Fixtures" || n.StartsWith("AcShadow.Fixtures.", StringComparison.Ordinal), n));
    }

    private static string Normalise(string text) => text.Replace("\r\n", "\n", StringComparison.Ordinal).TrimEnd('\n') + "\n";

    private static string Line(string[] lines, int index) => index < lines.Length ? lines[index].Trim() : "(end)";
}
