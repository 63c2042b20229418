using AcShadow.Tests.Support;

namespace AcShadow.Tests.Verify;

/// <summary>
/// docs/errors.md, "fixtures checked out": what a Windows checkout does to generated JSON (CRLF, a
/// byte-order mark) is named by verify, not reported as drift it cannot explain.
/// </summary>
public class CheckoutTests
{
    private static TempDir Batch()
    {
        var dir = new TempDir();
        Assert.Equal(0, CliRun.Of("batch", "--doors", "--out", dir.Path, "--quiet").ExitCode);
        return dir;
    }

    [Fact]
    public void Fixtures_whose_only_difference_is_CRLF_line_endings_are_said_to_differ_in_line_endings()
    {
        using var dir = Batch();
        var files = Directory.GetFiles(Path.Combine(dir.Path, "setups"));
        foreach (var file in files) File.WriteAllText(file, File.ReadAllText(file).Replace("\n", "\r\n"));

        var run = CliRun.Of("verify", "--fixtures", dir.Path);

        Assert.Equal(5, run.ExitCode);
        var changed = run.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries).Where(l => l.StartsWith("changed ", StringComparison.Ordinal)).ToArray();
        Assert.Equal(files.Length, changed.Length);
        Assert.All(changed, l => Assert.Contains("line endings differ (CRLF)", l));
        Assert.Contains("line endings differ (CRLF) only", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void An_index_with_a_byte_order_mark_is_named_as_such()
    {
        using var dir = Batch();
        var index = Path.Combine(dir.Path, "index.json");
        File.WriteAllBytes(index, [0xEF, 0xBB, 0xBF, .. File.ReadAllBytes(index)]);

        var run = CliRun.Of("verify", "--fixtures", dir.Path);

        Assert.Equal(2, run.ExitCode);
        Assert.Contains("starts with a UTF-8 byte-order mark", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void An_index_whose_strings_hold_bytes_that_are_not_UTF8_is_not_a_batch_index()
    {
        using var dir = Batch();
        var index = Path.Combine(dir.Path, "index.json");
        var bytes = File.ReadAllBytes(index);
        // A lone 0xE0 starts a three-byte sequence that never comes: valid JSON structure, invalid UTF-8.
        var at = bytes.AsSpan().IndexOf("\"path\": \""u8) + "\"path\": \""u8.Length;
        bytes[at] = 0xE0;
        File.WriteAllBytes(index, bytes);

        var run = CliRun.Of("verify", "--fixtures", dir.Path);

        Assert.Equal(2, run.ExitCode);
        Assert.Contains("is not a batch index: a string is not UTF-8 text", Assert.Single(run.ErrorLines, l => !l.Contains("SYNTHETIC")));
    }

    [Fact]
    public void The_repository_keeps_fixture_bytes_exact_on_checkout()
    {
        var attributes = Path.Combine(Fixtures.CommittedFixturesTests.RepositoryFixtures(), "..", ".gitattributes");
        Assert.True(File.Exists(attributes), ".gitattributes is missing");
        Assert.Contains(File.ReadAllLines(attributes), l => l.Trim().StartsWith("fixtures/**", StringComparison.Ordinal) && l.Contains("-text"));
    }
}
