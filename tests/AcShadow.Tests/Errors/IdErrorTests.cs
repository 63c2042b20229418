using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>docs/errors.md, "ids": malformed, outside the Setup range, of another type, absent from the dat.</summary>
public class IdErrorTests
{
    private static void AssertOneLine(CliRun run, int code, string message, TempDir output)
    {
        Assert.Equal(code, run.ExitCode);
        var line = Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC"));
        Assert.Contains(message, line);
        Assert.DoesNotContain("   at ", run.Error);
        Assert.Empty(output.Files());
    }

    [Theory]
    [InlineData("dump", "door", 2, "--setup: 'door' is not a Setup id: write it in hex, e.g. 0x020019FF")]
    [InlineData("chart", "door", 2, "--setup: 'door' is not a Setup id")]
    [InlineData("dump", "0x1234", 2, "--setup: 0x00001234 is outside the Setup range 0x02000000-0x0200FFFF")]
    [InlineData("chart", "0x02010000", 2, "--setup: 0x02010000 is outside the Setup range")]
    [InlineData("dump", "0x010044B5", 2, "--setup: 0x010044B5 is a GfxObj id, not a Setup id: pass an id in the Setup range 0x02000000-0x0200FFFF")]
    [InlineData("chart", "0x010044B5", 2, "is a GfxObj id, not a Setup id")]
    [InlineData("dump", "0xA9B4FFFE", 2, "--setup: 0xA9B4FFFE is a LandBlockInfo id (a cell dat object), not a Setup id")]
    [InlineData("dump", "0x08000123", 2, "--setup: 0x08000123 is a Surface id, not a Setup id")]
    [InlineData("dump", "0x0200FFFF", 4, "Setup 0x0200FFFF is not in the built-in synthetic sample: check the id")]
    [InlineData("chart", "0x0200FFFF", 4, "Setup 0x0200FFFF is not in the built-in synthetic sample")]
    public void A_bad_setup_id_is_one_line_with_its_code(string command, string id, int code, string message)
    {
        using var output = new TempDir();
        var run = CliRun.Of(command, "--setup", id, "--out", output.Path);
        AssertOneLine(run, code, message, output);
    }

    [Theory]
    [InlineData("batch", "0x020019FF\nnot-an-id\n", "--setups: ids.txt line 2: 'not-an-id' is not a Setup id")]
    [InlineData("audit", "0x010044B5\n", "--setups: ids.txt line 1: 0x010044B5 is outside the Setup range")]
    public void A_bad_line_in_a_setups_file_is_a_usage_error_naming_the_line(string command, string text, string message)
    {
        using var output = new TempDir();
        using var input = new TempDir();
        var list = Path.Combine(input.Path, "ids.txt");
        File.WriteAllText(list, text);
        var run = command == "batch"
            ? CliRun.Of("batch", "--setups", list, "--out", output.Path)
            : CliRun.Of("audit", "--setups", list, "--out", Path.Combine(output.Path, "audit.csv"));
        AssertOneLine(run, 2, message, output);
    }

    [Fact]
    public void Ids_a_batch_asks_for_that_the_dat_lacks_are_skipped_and_listed_not_fatal()
    {
        using var output = new TempDir();
        using var input = new TempDir();
        var list = Path.Combine(input.Path, "ids.txt");
        File.WriteAllText(list, "0x020019FF\n0x0200ABCD\n");
        var run = CliRun.Of("batch", "--setups", list, "--out", output.Path);
        Assert.Equal(0, run.ExitCode);
        Assert.Contains("skipped 1 (not in the dat; from setups-file): 0x0200ABCD", run.Out);
        Assert.Contains("setups/0x020019FF.shadow.json", output.Files());
    }

    [Theory]
    [InlineData("0xZZ", 2, "--landblock: '0xZZ' is not a landblock: write 0xXXYY, e.g. 0xA9B4")]
    [InlineData("0x0101", 4, "landblock 0x0101 has no LandBlockInfo (0x0101FFFE)")]
    public void A_bad_landblock_is_one_line_with_its_code(string landblock, int code, string message)
    {
        using var output = new TempDir();
        var run = CliRun.Of("batch", "--landblock", landblock, "--out", output.Path);
        AssertOneLine(run, code, message, output);
    }
}
