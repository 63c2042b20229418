using System.Diagnostics;
using AcShadow.Core.Json;
using AcShadow.Files;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md, "nothing half-written": a real batch process killed (SIGKILL) part-way through writing
/// leaves only whole files, no index.json, and temporary files that neither verify nor the next run
/// mistake for output; the next run removes them and completes the folder.
/// </summary>
[Trait("Speed", "Slow")]
public class InterruptedBatchTests
{
    [Fact]
    public void A_batch_killed_part_way_leaves_only_whole_files_and_the_next_run_completes_the_folder()
    {
        using var dir = new TempDir();
        var dats = Path.Combine(dir.Path, "dat");
        Directory.CreateDirectory(dats);
        var forged = SpecCompiler.Compile(ScaleSpecGenerator.Generate(400, 1));
        File.WriteAllBytes(Path.Combine(dats, "client_portal.dat"), forged.Portal);
        var whole = Path.Combine(dir.Path, "whole");
        var cut = Path.Combine(dir.Path, "cut");

        // The reference: the same batch, run to the end.
        var complete = CliRun.Of("batch", "--all", "--dat", dats, "--out", whole, "--jobs", "1", "--quiet");
        Assert.Equal(0, complete.ExitCode);
        var expectedFiles = Directory.GetFiles(whole, "*", SearchOption.AllDirectories).Length;

        using (var process = Process.Start(BuiltCli.Start([], "batch", "--all", "--dat", dats, "--out", cut, "--jobs", "1", "--quiet"))!)
        {
            // Output appears only once the export is done, file by file: kill as soon as the first lands
            // (the folder's lock file comes first, and is not output).
            while (!process.HasExited && !FilesUnder(cut).Any(IsOutput)) Thread.Sleep(2);
            Assert.False(process.HasExited, "the batch finished before it could be killed");
            process.Kill();
            process.WaitForExit();
        }

        Assert.False(File.Exists(Path.Combine(cut, "index.json")), "index.json is written last, so a killed run has none");
        // The killed run's lock file stays (empty of meaning: the lock died with the process); it is not output.
        var left = FilesUnder(cut).Where(IsOutput).ToArray();
        Assert.InRange(left.Length, 1, expectedFiles - 2);
        foreach (var file in left.Where(f => f.EndsWith(".shadow.json", StringComparison.Ordinal))) ShadowFileReader.Read(File.ReadAllText(file));
        foreach (var file in left.Where(f => f.EndsWith(".bsp.json", StringComparison.Ordinal))) BspFileReader.Read(File.ReadAllText(file));

        // verify against the complete run's index: files are missing, none changed (a truncated file would
        // be), none extra (a temporary file would be).
        File.Copy(Path.Combine(whole, "index.json"), Path.Combine(cut, "index.json"));
        var verify = CliRun.Of("verify", "--fixtures", cut, "--dat", dats);
        Assert.Equal(5, verify.ExitCode);
        Assert.Contains($"0 changed, {expectedFiles - 1 - left.Length} missing, 0 extra file(s)", verify.Error);
        Assert.DoesNotContain("changed ", verify.Out);
        Assert.DoesNotContain("extra ", verify.Out);

        // The next run into the folder removes what the killed one left and completes it.
        var again = CliRun.Of("batch", "--all", "--dat", dats, "--out", cut, "--jobs", "1", "--quiet");
        Assert.Equal(0, again.ExitCode);
        Assert.DoesNotContain(FilesUnder(cut), IsTemporary);
        Assert.Equal(0, CliRun.Of("verify", "--fixtures", cut, "--dat", dats).ExitCode);
    }

    private static string[] FilesUnder(string folder) =>
        Directory.Exists(folder) ? Directory.GetFiles(folder, "*", SearchOption.AllDirectories) : [];

    private static bool IsTemporary(string path) => path.EndsWith(".tmp", StringComparison.Ordinal);

    private static bool IsOutput(string path) => !IsTemporary(path) && Path.GetFileName(path) != FolderLock.FileName;
}
