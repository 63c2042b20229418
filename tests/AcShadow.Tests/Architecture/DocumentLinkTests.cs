using System.Text.RegularExpressions;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Architecture;

/// <summary>
/// Issue 32 item 15: the documents link only inside the repository (a link to a folder beside the clone is
/// broken in every clone but the author's), every link leads to a file that exists, and the retail rules
/// acshadow follows are a page of its own docs.
/// </summary>
public partial class DocumentLinkTests
{
    public static TheoryData<string> Documents()
    {
        var data = new TheoryData<string>();
        foreach (var name in new[] { "README.md", "CHANGELOG.md" }.Concat(Directory.GetFiles(Path.Combine(RepositoryRoot.Path, "docs"), "*.md").Select(f => "docs/" + Path.GetFileName(f))).Order(StringComparer.Ordinal))
            data.Add(name);
        return data;
    }

    [GeneratedRegex(@"\]\((?<target>[^)\s#]+)(#[^)]*)?\)")]
    private static partial Regex Link();

    [GeneratedRegex(@"\.\./shared/")]
    private static partial Regex SharedFolder();

    [Theory]
    [MemberData(nameof(Documents))]
    public void Every_relative_link_stays_inside_the_repository_and_leads_to_a_file(string document)
    {
        var path = Path.Combine(RepositoryRoot.Path, document);
        var text = File.ReadAllText(path);
        Assert.DoesNotMatch(SharedFolder(), text);
        foreach (Match m in Link().Matches(text))
        {
            var target = m.Groups["target"].Value;
            if (target.Contains("://", StringComparison.Ordinal) || target.StartsWith("mailto:", StringComparison.Ordinal)) continue;
            var resolved = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(path)!, target));
            Assert.True(resolved.StartsWith(RepositoryRoot.Path + Path.DirectorySeparatorChar, StringComparison.Ordinal), $"{document} links {target}, outside the repository");
            Assert.True(File.Exists(resolved) || Directory.Exists(resolved), $"{document} links {target}, which does not exist");
        }
    }

    [Fact]
    public void The_retail_rules_are_a_page_of_the_docs_that_the_readme_links()
    {
        var rules = Path.Combine(RepositoryRoot.Path, "docs", "retail-rules.md");
        Assert.True(File.Exists(rules));
        Assert.Contains("CPhysicsObj::FindObjCollisions", File.ReadAllText(rules));
        Assert.Contains("](docs/retail-rules.md)", File.ReadAllText(Path.Combine(RepositoryRoot.Path, "README.md")));
    }
}
