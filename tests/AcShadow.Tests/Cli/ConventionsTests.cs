using System.CommandLine;
using AcShadow.Cli.Commands;
using AcShadow.Cli.Conventions;
using AcShadow.Cli.Infrastructure;
using AcShadow.Cli;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

/// <summary>System.CommandLine conventions: help with examples, response files, typo suggestions, completion, --version, formats.</summary>
public class ConventionsTests
{
    public static TheoryData<string> Commands => new(CommandExamples.ByCommand.Keys.Where(k => k != "acshadow"));

    [Theory]
    [MemberData(nameof(Commands))]
    public void Every_subcommand_has_help_with_examples(string command)
    {
        var run = CliRun.Of(command, "--help");
        Assert.True(run.ExitCode == 0, run.Error);
        Assert.Contains("Usage:", run.Out);
        var examples = run.Out[run.Out.IndexOf("Examples:", StringComparison.Ordinal)..];
        Assert.All(CommandExamples.ByCommand[command], e => Assert.Contains(e, examples));
    }

    [Fact]
    public void Every_subcommand_of_the_app_has_examples()
    {
        var names = ExtraCommands.All(CliConsole.System()).Select(c => c.Name).Append("dump").Append("acshadow");
        Assert.Equal(names.Order(), CommandExamples.ByCommand.Keys.Order());
    }

    [Fact]
    public void Every_example_parses_without_errors()
    {
        var root = new RootCommand { DumpCommand.Create(CliConsole.System()) };
        foreach (var c in ExtraCommands.All(CliConsole.System())) root.Subcommands.Add(c);
        foreach (var example in CommandExamples.ByCommand.Values.SelectMany(e => e).Where(e => !e.Contains(" @")))
        {
            var words = example.Split(" >> ")[0].Split(' ', StringSplitOptions.RemoveEmptyEntries).Skip(1).ToArray();
            var parse = root.Parse(words);
            Assert.True(parse.Errors.Count == 0, $"{example}: {string.Join("; ", parse.Errors.Select(e => e.Message))}");
        }
    }

    [Fact]
    public void A_response_file_supplies_the_arguments()
    {
        using var dir = new TempDir();
        var rsp = Path.Combine(dir.Path, "dump-door.rsp");
        File.WriteAllLines(rsp, ["dump", "--setup 0x020019FF", "--out", Path.Combine(dir.Path, "out"), "--format both"]);
        var run = CliRun.Of("@" + rsp);
        Assert.True(run.ExitCode == 0, run.Error);
        Assert.True(File.Exists(Path.Combine(dir.Path, "out", "gfxobjs", "0x010044B5.gfxobj.json")));
    }

    [Theory]
    [InlineData(new[] { "dumpp" }, "Did you mean 'dump'?")]
    [InlineData(new[] { "dump", "--setp", "0x020019FF" }, "Did you mean '--setup'?")]
    [InlineData(new[] { "batch", "--out", "x", "--dors" }, "Did you mean '--doors'?")]
    [InlineData(new[] { "audit", "--verbos" }, "Did you mean '--verbose'?")]
    public void A_mistyped_command_or_option_gets_a_suggestion(string[] args, string suggestion)
    {
        var run = CliRun.Of(args);
        Assert.Equal(2, run.ExitCode);
        Assert.Single(run.ErrorLines);
        Assert.Contains(suggestion, run.Error);
    }

    [Fact]
    public void A_word_close_to_nothing_gets_no_suggestion()
    {
        var run = CliRun.Of("frobnicate");
        Assert.Equal(2, run.ExitCode);
        Assert.DoesNotContain("Did you mean", run.Error);
    }

    [Theory]
    [InlineData("acshadow d", "dump")]
    [InlineData("acshadow dump --se", "--setup")]
    [InlineData("acshadow batch --format a", "acdream")]
    public void The_suggest_directive_completes_commands_options_and_values(string line, string expected)
    {
        var run = CliRun.Of($"[suggest:{line.Length}]", line);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains(expected, run.Out.Split('\n', StringSplitOptions.TrimEntries));
    }

    [Fact]
    public void Completion_scripts_for_bash_and_pwsh_use_the_suggest_directive()
    {
        var bash = CliRun.Of("completions", "bash");
        Assert.Equal(0, bash.ExitCode);
        Assert.Contains("complete -o default -F _acshadow_complete acshadow", bash.Out);
        Assert.Contains("[suggest:${COMP_POINT}]", bash.Out);
        Assert.DoesNotContain("\r", bash.Out);
        var pwsh = CliRun.Of("completions", "pwsh");
        Assert.Contains("Register-ArgumentCompleter -Native -CommandName acshadow", pwsh.Out);
        var fish = CliRun.Of("completions", "fish");
        Assert.Equal(2, fish.ExitCode);
        Assert.Single(fish.ErrorLines);
    }

    [Fact]
    public void Version_names_the_tool_version_and_the_dat_layer()
    {
        var run = CliRun.Of("--version");
        Assert.Equal(0, run.ExitCode);
        var lines = run.Out.Split('\n');
        Assert.Matches(@"^acshadow \d+\.\d+\.\d+", lines[0]);
        Assert.StartsWith("dat layer: in-house AcShadow.Core", lines[1]);
        Assert.Contains("Chorizite.DatReaderWriter: not used", lines[1]);
    }

    [Fact]
    public void Formats_lists_every_format_with_its_schema()
    {
        var run = CliRun.Of("formats");
        Assert.Equal(0, run.ExitCode);
        Assert.All(FileFormats.All, f => Assert.Contains($"{f.Format}", run.Out));
        Assert.All(FileFormats.All, f => Assert.Contains($"{f.SchemaId}", run.Out));
    }
}
