using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

public class AppTests
{
    [Fact]
    public void No_command_is_a_usage_error_pointing_at_the_root_help()
    {
        var run = CliRun.Of();
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("(see `acshadow --help`)", Assert.Single(run.ErrorLines));
    }

    [Fact]
    public void An_unknown_command_is_named()
    {
        var run = CliRun.Of("frobnicate");
        Assert.Equal(2, run.ExitCode);
        Assert.Contains("'frobnicate'", Assert.Single(run.ErrorLines));
    }

    [Fact]
    public void An_unknown_option_is_named_with_its_command_help()
    {
        var run = CliRun.Of("dump", "--setup", "0x020019FF", "--bogus");
        Assert.Equal(2, run.ExitCode);
        var line = Assert.Single(run.ErrorLines);
        Assert.Contains("'--bogus'", line);
        Assert.Contains("acshadow dump --help", line);
    }

    [Fact]
    public void Help_lists_every_subcommand_and_exits_zero()
    {
        var run = CliRun.Of("--help");
        Assert.Equal(0, run.ExitCode);
        foreach (var command in new[] { "dump", "batch", "audit", "verify", "chart" }) Assert.Contains(command, run.Out);
    }
}
