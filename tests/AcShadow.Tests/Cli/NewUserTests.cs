using System.Text.RegularExpressions;
using System.Xml.Linq;
using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

/// <summary>
/// Issue 32 item 16 (and doctor's columns, item 18): what a new user trips on. The cell dat is found in the
/// folder --dat names or through ACSHADOW_CELL_DAT, and doctor says when it checked no cells; verify of a
/// folder without index.json is a usage error (exit 2) whoever wrote it; its drift hint names no script a
/// consumer's repository lacks; the packed tool carries a readme.
/// </summary>
public class NewUserTests
{
    [Fact]
    public void Doctor_on_a_dat_folder_checks_the_cell_dat_in_it()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var run = CliRun.Of("doctor", "--dat", dir.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Matches(@"cell dat: +\d+ bytes", run.Out);
        Assert.DoesNotContain("no cell dat", run.Out);
    }

    [Fact]
    public void The_cell_dat_environment_variable_names_the_cell_dat()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var portal = Path.Combine(dir.Path, "client_portal.dat");
        var cell = Path.Combine(dir.Path, "client_cell_1.dat");
        var run = CliRun.With(name => name == "ACSHADOW_CELL_DAT" ? cell : null, "doctor", "--dat", portal);
        Assert.Equal(0, run.ExitCode);
        Assert.Matches(@"cell dat: +\d+ bytes", run.Out);
        var missing = CliRun.With(name => name == "ACSHADOW_CELL_DAT" ? cell + ".gone" : null, "doctor", "--dat", portal);
        Assert.Equal(3, missing.ExitCode);
        Assert.Contains("acshadow: ACSHADOW_CELL_DAT: ", missing.Error);
    }

    [Fact]
    public void Doctor_without_a_cell_dat_says_it_checked_no_cells_and_its_columns_never_run_together()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var run = CliRun.Of("doctor", "--dat", Path.Combine(dir.Path, "client_portal.dat"));
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("cell dat:   not checked (none given: pass --cell-dat", run.Out);
        Assert.Contains("not checked; the cell dat's LandBlockInfos not checked (no cell dat)", run.Out);
        // "not applicable" is the widest verdict: a space always follows it.
        Assert.DoesNotMatch(new Regex(@"^  (holds|differs|not applicable|not checked)[a-z]", RegexOptions.Multiline), run.Out);
    }

    [Fact]
    public void A_not_applicable_verdict_is_followed_by_a_space_before_its_check()
    {
        var report = Doctor.DoctorDats.Report(Doctor.DoctorDats.Portal(Doctor.DoctorDats.SampleObjects()));
        var first = report.Checks[0] with { Verdict = AcShadow.Analysis.Doctor.DoctorVerdict.NotApplicable };
        var summary = AcShadow.Analysis.Doctor.DoctorReportWriter.Summary(report with { Checks = [first, .. report.Checks.Skip(1)] }, "a dat");
        Assert.Contains($"  not applicable  {first.Key}", summary);
    }

    [Fact]
    public void A_found_cell_dat_is_never_written_over_by_a_report()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var cell = Path.Combine(dir.Path, "client_cell_1.dat");
        var before = File.ReadAllBytes(cell);
        var run = CliRun.Of("doctor", "--dat", dir.Path, "--out", cell);
        Assert.Equal(6, run.ExitCode);
        Assert.Equal(before, File.ReadAllBytes(cell));
    }

    [Fact]
    public void Verify_of_a_folder_dump_wrote_is_exit_2_with_a_clear_line()
    {
        using var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path).ExitCode);
        var run = CliRun.Of("verify", "--fixtures", dir.Path);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--fixtures: {dir.Path} has no index.json, so it is no finished batch", Assert.Single(run.ErrorLines, l => l.StartsWith("acshadow: --", StringComparison.Ordinal)));
    }

    [Fact]
    public void The_drift_hint_names_no_script_of_this_repository()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var fixtures = Path.Combine(dir.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--dat", dir.Path, "--out", fixtures, "--quiet").ExitCode);
        File.AppendAllText(Path.Combine(fixtures, "setups", "0x020019FF.shadow.json"), " ");
        var run = CliRun.Of("verify", "--fixtures", fixtures, "--dat", dir.Path);
        Assert.Equal(5, run.ExitCode);
        Assert.Contains("run `acshadow batch` into the folder again", run.Error);
        Assert.DoesNotContain("scripts/", run.Error);
    }

    [Fact]
    public void The_packed_tool_carries_the_readme()
    {
        var project = XDocument.Load(Path.Combine(RepositoryRoot.Path, "src", "AcShadow.Cli", "AcShadow.Cli.csproj"));
        var readme = project.Descendants("PackageReadmeFile").Single().Value;
        var packed = project.Descendants("None").Single(n => (string?)n.Attribute("Pack") == "true" && Path.GetFileName(((string)n.Attribute("Include")!).Replace('\\', '/')) == readme);
        var source = Path.Combine(RepositoryRoot.Path, "src", "AcShadow.Cli", ((string)packed.Attribute("Include")!).Replace('\\', '/'));
        Assert.True(File.Exists(source), $"{source} is missing");
        Assert.Equal("\\", (string?)packed.Attribute("PackagePath"));
    }
}
