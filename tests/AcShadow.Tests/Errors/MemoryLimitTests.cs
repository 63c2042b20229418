using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// Issue 32 item 13: under `ulimit -v` a command finishes or says in one line that memory ran out (exit 1),
/// never an abort (134, "Failed to create RW mapping", "No usable version of libssl"), an "internal error"
/// or a line blaming `ulimit -n`; and files read back whole are refused past a documented size instead of
/// growing the process by ten times their size (docs/errors.md, "Limits": 64 MiB a fixture file, 256 MiB a compiled scene).
/// </summary>
public class MemoryLimitTests
{
    /// <summary>acshadow under a virtual-memory limit, as a user's shell would run it (without the test's W^X setting).</summary>
    private static (int ExitCode, string Out, string Error) Limited(long kibibytes, string args) =>
        BuiltCli.RunShell([], $"unset DOTNET_EnableWriteXorExecute; ulimit -v {kibibytes}; exec dotnet '{BuiltCli.Dll}' {args}");


    [Theory]
    [InlineData("doctor")]
    [InlineData("verify")]
    [InlineData("batch")]
    public void Under_a_2_gb_limit_a_command_finishes(string command)
    {
        using var dir = new TempDir();
        var run = Limited(2_000_000, Args(command, dir.Path));
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Error}");
    }

    [Theory]
    [InlineData("doctor")]
    [InlineData("verify")]
    [InlineData("batch")]
    public void Under_a_tight_limit_a_command_finishes_or_says_memory_ran_out_in_one_line(string command)
    {
        using var dir = new TempDir();
        var run = Limited(1_200_000, Args(command, dir.Path));
        Assert.Contains(run.ExitCode, new[] { 0, 1 });
        if (run.ExitCode == 1)
        {
            var line = Assert.Single(run.Error.Split('\n', StringSplitOptions.RemoveEmptyEntries), l => !l.Contains("SYNTHETIC", StringComparison.Ordinal));
            Assert.StartsWith("acshadow: out of memory: the virtual-memory limit is ", line);
        }
        Assert.DoesNotContain("internal error", run.Error);
        Assert.DoesNotContain("ulimit -n", run.Error);
        Assert.DoesNotContain("Fatal error", run.Error);
    }

    private static string Args(string command, string scratch) => command switch
    {
        "verify" => $"verify --fixtures '{Path.Combine(RepositoryRoot.Path, "fixtures")}'",
        "batch" => $"batch --all --out '{Path.Combine(scratch, "out")}' --quiet",
        _ => command,
    };

    [Fact]
    public void Verify_refuses_a_fixture_larger_than_the_limit_before_reading_it()
    {
        using var dir = SampleDat.WriteToTempFolder();
        var fixtures = Path.Combine(dir.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--dat", dir.Path, "--out", fixtures, "--quiet").ExitCode);
        var shadow = Path.Combine(fixtures, "setups", "0x020019FF.shadow.json");
        using (var file = File.OpenWrite(shadow)) file.SetLength((64L << 20) + 1);
        var run = CliRun.Of("verify", "--fixtures", fixtures, "--dat", dir.Path);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--fixtures: {shadow} is 64 MiB, more than the 64 MiB acshadow reads back from one file", run.Error);
    }

    [Fact]
    public void View_refuses_a_compiled_scene_larger_than_the_limit_before_reading_it()
    {
        using var dir = new TempDir();
        var scene = Path.Combine(dir.Path, "scene");
        Assert.Equal(0, CliRun.Of("scene", "--landblock", "0xA9B4", "--out", scene, "--quiet").ExitCode);
        var compiled = Path.Combine(scene, "compiled-scene.json");
        using (var file = File.OpenWrite(compiled)) file.SetLength((256L << 20) + 1);
        var run = CliRun.Of("view", "--scene", scene, "--out", Path.Combine(dir.Path, "view"));
        Assert.Equal(2, run.ExitCode);
        Assert.Contains($"--scene: {compiled} is 256 MiB, more than the 256 MiB", run.Error);
    }
}
