using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.View;

public sealed class ViewErrorTests
{
    [Fact]
    public void View_usage_errors_are_one_line_with_exit_2()
    {
        using var dir = new TempDir();
        var cases = new (string[] Args, string Expected)[]
        {
            (["view", "--out", dir.Path], "choose what to view"),
            (["view", "--fixtures", CommittedFixturesTests.RepositoryFixtures(), "--dat", dir.Path, "--out", dir.Path], "--fixtures reads only the folder's JSON"),
            (["view", "--setup", "0x020019FF", "--chart", dir.Path, "--out", dir.Path], "failures.csv does not exist"),
            (["view", "--landblock", "0xZZ", "--out", dir.Path], "is not a landblock"),
        };
        foreach (var (args, expected) in cases)
        {
            var run = CliRun.Of(args);
            Assert.Equal(2, run.ExitCode);
            Assert.Contains(expected, Assert.Single(run.ErrorLines));
        }
        Assert.Empty(dir.Files());
    }

    [Fact]
    public void A_setup_view_cannot_find_is_exit_4()
    {
        using var dir = new TempDir();
        var fromDat = CliRun.Of("view", "--setup", "0x0200FFFF", "--out", dir.Path);
        Assert.Equal(4, fromDat.ExitCode);
        Assert.Contains("Setup 0x0200FFFF is not in", fromDat.ErrorLines.Last());
        var fromFixtures = CliRun.Of("view", "--fixtures", CommittedFixturesTests.RepositoryFixtures(), "--setup", "0x0200FFFF", "--out", dir.Path);
        Assert.Equal(4, fromFixtures.ExitCode);
        Assert.Contains("no shadow file for Setup 0x0200FFFF", Assert.Single(fromFixtures.ErrorLines));
        Assert.Empty(dir.Files());
    }
}
