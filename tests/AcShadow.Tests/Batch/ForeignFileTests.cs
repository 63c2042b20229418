using AcShadow.Tests.Support;
using static AcShadow.Tests.Batch.BatchRuns;

namespace AcShadow.Tests.Batch;

/// <summary>
/// batch streams its files, so it checks the folder for files it does not own before it writes the first
/// one: a user's file where a batch file goes stops the run with nothing written.
/// </summary>
public sealed class ForeignFileTests
{
    [Theory]
    [InlineData("setups/0x020019FF.shadow.json")]
    [InlineData("gfxobjs/0x010044B6.bsp.json")]
    [InlineData("index.json")]
    public void A_users_file_where_a_batch_file_goes_stops_the_run_before_anything_is_written(string path)
    {
        using var dir = new TempDir();
        var target = Path.Combine(dir.Path, path);
        Directory.CreateDirectory(Path.GetDirectoryName(target)!);
        File.WriteAllText(target, "my own notes\n");

        var run = CliRun.Of("batch", "--out", dir.Path, "--doors");

        Assert.Equal(6, run.ExitCode);
        Assert.Contains("not acshadow output", run.Error);
        Assert.Equal([path], dir.Files());
        Assert.Equal("my own notes\n", File.ReadAllText(target));
    }

    [Fact]
    public void A_folder_an_earlier_batch_wrote_is_written_again()
    {
        var (first, dir) = RunBatch("--doors");
        using (dir)
        {
            Assert.Equal(0, first.ExitCode);
            File.Delete(Path.Combine(dir.Path, "index.json")); // no index: ownership comes from the files' own format lines
            var second = CliRun.Of("batch", "--out", dir.Path, "--doors");
            Assert.Equal(0, second.ExitCode);
        }
    }
}
