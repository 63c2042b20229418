using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>docs/errors.md: every error is one line on stderr; --verbose adds the stack trace; audit's --out file.</summary>
public class ErrorLineTests
{
    public static TheoryData<string> Commands => new() { "dump", "batch", "audit", "verify", "chart" };

    private static string[] Args(string command, string outDir) => command switch
    {
        "dump" => ["dump", "--setup", "0x020019FF", "--out", outDir],
        "batch" => ["batch", "--all", "--out", outDir],
        "audit" => ["audit"],
        "verify" => ["verify", "--fixtures", Fixtures.CommittedFixturesTests.RepositoryFixtures()],
        "chart" => ["chart", "--setup", "0x020019FF", "--out", outDir],
        _ => throw new ArgumentOutOfRangeException(nameof(command)),
    };

    [Theory]
    [MemberData(nameof(Commands))]
    public void An_error_is_one_line_without_a_stack_trace_and_verbose_adds_it(string command)
    {
        using var output = new TempDir();
        string[] bad = ["--dat", "/nonexistent/client_portal.dat"];

        var plain = CliRun.Of([.. Args(command, output.Path), .. bad]);
        var verbose = CliRun.Of([.. Args(command, output.Path), .. bad, "--verbose"]);

        Assert.Equal(3, plain.ExitCode);
        Assert.StartsWith("acshadow: --dat: ", Assert.Single(plain.ErrorLines));
        Assert.DoesNotContain("   at ", plain.Error);
        Assert.Equal(3, verbose.ExitCode);
        Assert.Equal(plain.ErrorLines[0], verbose.ErrorLines[0]);
        Assert.Contains("   at AcShadow.Cli.", verbose.Error);
    }

    [Fact]
    public void An_audit_report_that_cannot_be_written_is_exit_6_and_leaves_no_temporary_file()
    {
        var run = CliRun.Of("audit", "--out", "/proc/acshadow-test/audit.csv");
        Assert.Equal(6, run.ExitCode);
        Assert.Contains("cannot write /proc/acshadow-test/audit.csv", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void An_audit_report_named_explicitly_replaces_the_file_of_that_name()
    {
        using var dir = new TempDir();
        var report = Path.Combine(dir.Path, "audit.csv");
        File.WriteAllText(report, "an older report\n");
        var run = CliRun.Of("audit", "--out", report);
        Assert.Equal(0, run.ExitCode);
        Assert.StartsWith("id,", File.ReadAllText(report));
        Assert.Equal(["audit.csv"], dir.Files());
    }
}
