using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md: each failure exits with the code of its own class, in one line, with no runtime stack
/// trace: stdout that cannot be written, an empty --out, unreadable fixtures, closed stderr, no file
/// descriptors left.
/// </summary>
public class TruthfulExitTests
{
    private static string Acshadow => $"dotnet '{BuiltCli.Dll}'";

    private static string[] Lines(string text) => text.Split('\n', StringSplitOptions.RemoveEmptyEntries);

    private static void NoStackTrace(string stderr) => Assert.DoesNotContain(Lines(stderr), l => l.TrimStart().StartsWith("at ", StringComparison.Ordinal) || l.Contains("Unhandled exception"));

    [Theory]
    [InlineData("> /dev/full")]
    [InlineData(">&-")]
    public void Stdout_that_cannot_be_written_is_exit_6_not_a_dat_error(string redirection)
    {
        var (code, _, error) = BuiltCli.RunShell([], $"{Acshadow} formats {redirection}");
        Assert.Equal(6, code);
        Assert.Contains("acshadow: cannot write to standard output", Assert.Single(Lines(error)));
    }

    [Fact]
    public void A_closed_stderr_ends_with_the_exit_code_and_no_stack_trace()
    {
        using var dir = new TempDir();
        var file = Path.Combine(dir.Path, "taken");
        File.WriteAllText(file, "x");
        // stderr closed, stdout captured: the error has nowhere to go, the exit code still tells.
        var (code, output, _) = BuiltCli.RunShell([], $"{Acshadow} dump --setup 0x020019FF --out '{file}' 2>&-");
        Assert.Equal(6, code);
        NoStackTrace(output);
    }

    [Theory]
    [InlineData(24)]
    [InlineData(64)]
    [InlineData(127)]
    public void A_descriptor_limit_below_the_minimum_is_refused_in_one_line_before_anything_runs(int limit)
    {
        using var dir = new TempDir();
        var (code, _, error) = BuiltCli.RunShell([], $"ulimit -n {limit}; {Acshadow} batch --doors --all --out '{dir.Path}/out' --quiet");
        Assert.Equal(1, code);
        Assert.Equal($"acshadow: the open-file limit (ulimit -n) is {limit}, too few to run: acshadow needs at least 128 (raise it, e.g. `ulimit -n 1024`)", Assert.Single(Lines(error)));
        Assert.False(Directory.Exists(Path.Combine(dir.Path, "out")));
    }

    [Fact]
    public void At_the_minimum_descriptor_limit_a_parallel_batch_runs()
    {
        using var dir = new TempDir();
        var (code, _, error) = BuiltCli.RunShell([], $"ulimit -n 128; {Acshadow} batch --doors --all --jobs 8 --out '{dir.Path}/out' --quiet");
        Assert.True(code == 0, error);
        Assert.True(File.Exists(Path.Combine(dir.Path, "out", "index.json")));
    }

    [Fact]
    public void Where_the_runtime_barely_starts_acshadow_still_says_one_line_without_a_stack_trace()
    {
        // Below about 20 descriptors the runtime cannot load its JIT and never reaches acshadow (its own
        // failure, not ours); just above, acshadow's first step may itself be short of descriptors. Whatever
        // acshadow says there is one line; the sweep must reach acshadow at least once to prove anything.
        var reached = 0;
        for (var limit = 16; limit <= 40; limit++)
        {
            var (code, _, error) = BuiltCli.RunShell([], $"ulimit -n {limit}; {Acshadow} formats");
            if (!error.Contains("acshadow", StringComparison.Ordinal)) continue;
            reached++;
            Assert.Equal(1, code);
            NoStackTrace(error);
            Assert.StartsWith("acshadow: ", Assert.Single(Lines(error)));
        }
        Assert.True(reached > 0, "no limit from 16 to 40 let the runtime reach acshadow");
    }

    [Theory]
    [InlineData("dump")]
    [InlineData("batch")]
    [InlineData("chart")]
    [InlineData("view")]
    [InlineData("dump-cell")]
    public void An_empty_out_is_a_usage_error(string command)
    {
        string[] args = command switch
        {
            "dump" => ["dump", "--setup", "0x020019FF", "--out", ""],
            "batch" => ["batch", "--doors", "--out", ""],
            "view" => ["view", "--setup", "0x020019FF", "--out", ""],
            "dump-cell" => ["dump", "--cell", "0xA9B40100", "--out", ""],
            _ => ["chart", "--setup", "0x020019FF", "--out", ""],
        };
        var run = CliRun.Of(args);
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("--out: the path is empty", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
        Assert.Equal(2, CliRun.Of("audit", "--doors", "--out", "").ExitCode);
        Assert.Equal(2, CliRun.Of("doctor", "--out", "").ExitCode);
    }

    [Fact]
    public void An_unreadable_fixture_or_index_under_verify_is_a_usage_error_naming_it()
    {
        using var dir = new TempDir();
        BuiltCli.OpenToEveryone(dir.Path);
        var fixtures = Path.Combine(dir.Path, "fixtures");
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--out", fixtures, "--quiet").ExitCode);
        foreach (var folder in Directory.GetDirectories(fixtures, "*", SearchOption.AllDirectories).Append(fixtures)) BuiltCli.OpenToEveryone(folder);
        foreach (var file in Directory.GetFiles(fixtures, "*", SearchOption.AllDirectories))
            BuiltCli.SetMode(file, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead);
        var shadow = Directory.GetFiles(Path.Combine(fixtures, "setups"))[0];
        BuiltCli.SetMode(shadow, UnixFileMode.UserRead | UnixFileMode.UserWrite);

        var (code, _, error) = BuiltCli.Run(BuiltCli.AsUnprivilegedUser(), "verify", "--fixtures", fixtures);
        Assert.Equal(2, code);
        Assert.Contains($"--fixtures: cannot read {shadow}", Assert.Single(Lines(error), l => !l.Contains("SYNTHETIC")));

        BuiltCli.SetMode(Path.Combine(fixtures, "index.json"), UnixFileMode.UserRead | UnixFileMode.UserWrite);
        (code, _, error) = BuiltCli.Run(BuiltCli.AsUnprivilegedUser(), "verify", "--fixtures", fixtures);
        Assert.Equal(2, code);
        Assert.Contains("--fixtures: cannot read", Assert.Single(Lines(error), l => !l.Contains("SYNTHETIC")));
        NoStackTrace(error);
    }
}
