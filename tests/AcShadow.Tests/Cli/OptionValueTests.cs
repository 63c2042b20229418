using System.Globalization;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Cli;

/// <summary>
/// Option values are parsed with the command line (ValueOptions, NumberRule), yet a bad one is still the
/// command's own usage line: no pointer to the help, exit 2, the stack trace only with --verbose.
/// </summary>
public class OptionValueTests
{
    [Theory]
    [InlineData(new[] { "dump", "--setup", "0x020019FF", "--scale", "1,5" }, "--scale: '1,5' is not a positive number: use e.g. 1 or 1.5")]
    [InlineData(new[] { "dump", "--setup", "0x020019FF", "--scale", "Infinity" }, "--scale: 'Infinity' is not a positive number: use e.g. 1 or 1.5")]
    [InlineData(new[] { "batch", "--out", "unused", "--doors", "--jobs", "+3" }, "--jobs: '+3' is not a worker count: use a whole number from 1 to 1024")]
    [InlineData(new[] { "batch", "--out", "unused", "--doors", "--jobs", "1025" }, "--jobs: '1025' is not a worker count: use a whole number from 1 to 1024")]
    [InlineData(new[] { "chart", "--out", "unused", "--setup", "0x020019FF", "--probe-radius", "NaN" }, "--probe-radius: 'NaN' is not a positive number of metres: use e.g. 0.5")]
    [InlineData(new[] { "scene", "--out", "unused", "--landblock", "0xA9B4", "--mover-radius", "0.5", "--mover-radius", "-1" }, "--mover-radius: '-1' is not a positive number of metres: use e.g. 0.48")]
    [InlineData(new[] { "scene", "--out", "unused", "--landblock", "0xA9B4", "--tolerance", "100.5" }, "--tolerance: '100.5' is not a percentage from 0 to 100: use e.g. 0.5")]
    [InlineData(new[] { "audit", "--max-coverage", "-0.1" }, "--max-coverage: '-0.1' is not a fraction: use a number from 0 to 1, e.g. 0.1")]
    [InlineData(new[] { "view", "--setup", "0x020019FF", "--setup", "dead" }, "--setup: 0x0000DEAD is outside the Setup range 0x02000000-0x0200FFFF")]
    public void A_bad_value_is_one_line_of_its_own_with_exit_2(string[] args, string line)
    {
        var run = CliRun.Of(args);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal("acshadow: " + line, Assert.Single(run.ErrorLines));
        Assert.Empty(run.Out);
    }

    [Fact]
    public void Numbers_read_the_same_whatever_the_culture()
    {
        var culture = CultureInfo.CurrentCulture;
        try
        {
            // German writes 1,5 for 1.5 and 1.000 for a thousand: neither may be read so.
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");
            Assert.Equal("acshadow: --scale: '1,5' is not a positive number: use e.g. 1 or 1.5",
                Assert.Single(CliRun.Of("dump", "--setup", "0x020019FF", "--scale", "1,5").ErrorLines));
            Assert.Equal("acshadow: --scale: 2.000e3 is outside 0.001-1000: no object is scaled that far, and geometry that small or large loses its precision",
                Assert.Single(CliRun.Of("dump", "--setup", "0x020019FF", "--scale", "2.000e3").ErrorLines));
        }
        finally
        {
            CultureInfo.CurrentCulture = culture;
        }
    }

    [Fact]
    public void Another_parse_error_is_reported_before_a_bad_value_with_the_help_pointer()
    {
        var unknown = CliRun.Of("dump", "--scale", "x", "--bogus");
        Assert.Equal(2, unknown.ExitCode);
        Assert.Equal("acshadow: Unrecognized command or argument '--bogus'. (see `acshadow dump --help`)", Assert.Single(unknown.ErrorLines));

        var missing = CliRun.Of("batch", "--doors", "--jobs", "0");
        Assert.Equal(2, missing.ExitCode);
        Assert.Equal("acshadow: Option '--out' is required. (see `acshadow batch --help`)", Assert.Single(missing.ErrorLines));
    }

    [Fact]
    public void Of_two_bad_values_the_first_the_command_declares_is_reported()
    {
        var run = CliRun.Of("dump", "--policy", "strict", "--setup", "dead");
        Assert.Equal(2, run.ExitCode);
        Assert.Equal("acshadow: --setup: 0x0000DEAD is outside the Setup range 0x02000000-0x0200FFFF", Assert.Single(run.ErrorLines));
    }

    [Fact]
    public void Verbose_adds_the_stack_trace_after_a_bad_value_line()
    {
        var plain = CliRun.Of("dump", "--setup", "0x020019FF", "--pose", "sitting");
        var verbose = CliRun.Of("dump", "--setup", "0x020019FF", "--pose", "sitting", "--verbose");
        Assert.Equal(2, verbose.ExitCode);
        Assert.Equal("acshadow: --pose: 'sitting' is not a pose: use retail (the default) or placement", Assert.Single(plain.ErrorLines));
        Assert.Equal(plain.ErrorLines[0], verbose.ErrorLines[0]);
        Assert.Contains("   at AcShadow.Cli.", verbose.Error);
    }

    [Fact]
    public void Help_shows_a_bad_value_no_error_and_typed_options_by_their_help_names()
    {
        var run = CliRun.Of("dump", "--scale", "x", "--help");
        Assert.Equal(0, run.ExitCode);
        Assert.Empty(run.Error);
        foreach (var shown in new[] { "--setup <ID>", "--cell <ID>", "--policy <retail|union>", "--scale <S>", "--format <canonical|acdream|both>", "--pose <retail|placement>", "--state <closed|open>", "--motion-table <ID>" })
            Assert.Contains(shown, run.Out);
        var chart = CliRun.Of("chart", "--help").Out;
        foreach (var shown in new[] { "--setup <ID>", "--landblock <0xXXYY>", "--probe-radius <R>", "--spacing <S>", "--jobs <N>" })
            Assert.Contains(shown, chart);
    }

    [Theory]
    [InlineData("acshadow dump --policy ")]
    [InlineData("acshadow dump --pose ")]
    [InlineData("acshadow audit --format ")]
    public void Typed_names_complete_as_text_did_not_as_their_CSharp_enum_names(string line)
    {
        var run = CliRun.Of($"[suggest:{line.Length}]", line);
        Assert.Equal(0, run.ExitCode);
        Assert.Empty(run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries));
    }
}
