using System.Text.RegularExpressions;
using System.Xml.Linq;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// Every source file's namespace is its project's root namespace followed by its folders, so a type is found
/// where its name says and a consumer's <c>using</c> names the assembly it comes from.
/// </summary>
public partial class NamespaceLayoutTests
{
    [GeneratedRegex(@"^namespace\s+([\w.]+)\s*[;{]", RegexOptions.Multiline)]
    private static partial Regex NamespaceDeclaration();

    public static TheoryData<string> Projects()
    {
        var data = new TheoryData<string>();
        foreach (var top in new[] { "src", "tools", "tests" })
            foreach (var project in Directory.EnumerateFiles(Path.Combine(RepositoryRoot.Path, top), "*.csproj", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
                data.Add(Path.GetRelativePath(RepositoryRoot.Path, project).Replace('\\', '/'));
        return data;
    }

    [Theory]
    [MemberData(nameof(Projects))]
    public void Namespaces_follow_the_project_and_its_folders(string project)
    {
        var projectFile = Path.Combine(RepositoryRoot.Path, project);
        var projectDir = Path.GetDirectoryName(projectFile)!;
        var root = XDocument.Load(projectFile).Descendants("RootNamespace").Select(e => e.Value).FirstOrDefault()
                   ?? Path.GetFileNameWithoutExtension(projectFile);
        var wrong = new List<string>();
        var checkedFiles = 0;
        foreach (var file in Directory.EnumerateFiles(projectDir, "*.cs", SearchOption.AllDirectories))
        {
            var relative = Path.GetRelativePath(projectDir, file).Replace('\\', '/');
            if (relative.StartsWith("obj/", StringComparison.Ordinal) || relative.StartsWith("bin/", StringComparison.Ordinal)) continue;
            var folder = Path.GetDirectoryName(relative)!.Replace('\\', '/');
            var expected = folder.Length == 0 ? root : root + "." + folder.Replace('/', '.');
            var declared = NamespaceDeclaration().Matches(File.ReadAllText(file)).Select(m => m.Groups[1].Value).ToArray();
            checkedFiles++;
            // A top-level program (Program.cs with no namespace) is the one file allowed to declare none.
            if (declared.Length == 0 && Path.GetFileName(file) == "Program.cs" && folder.Length == 0) continue;
            if (declared.Length != 1 || declared[0] != expected)
                wrong.Add($"{relative}: declares {(declared.Length == 0 ? "no namespace" : string.Join(", ", declared))}, expected {expected}");
        }
        Assert.True(checkedFiles > 0, $"{project} has no source files");
        Assert.True(wrong.Count == 0, $"{project}:\n" + string.Join("\n", wrong));
    }
}
