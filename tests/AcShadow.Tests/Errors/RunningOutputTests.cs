using System.Diagnostics;
using AcShadow.Files;
using AcShadow.Forge.Scale;
using AcShadow.Forging;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// docs/errors.md, "the folder while a run writes" and "signals": one writer per folder, a folder moved
/// away mid-run, a dat truncated mid-run, Ctrl-C, a file-size limit, each on a real process.
/// </summary>
public class RunningOutputTests
{
    /// <summary>A forged dat big enough that a batch is still writing when the test acts (400 Setups).</summary>
    private static readonly Lazy<byte[]> LongDat = new(() => SpecCompiler.Compile(ScaleSpecGenerator.Generate(400, 1)).Portal);

    private static string WriteLongDat(TempDir dir)
    {
        var dats = Path.Combine(dir.Path, "dat");
        Directory.CreateDirectory(dats);
        File.WriteAllBytes(Path.Combine(dats, "client_portal.dat"), LongDat.Value);
        return dats;
    }

    private static string[] Lines(string text) => text.Split('\n', StringSplitOptions.RemoveEmptyEntries);

    /// <summary>Stderr without the plain progress lines ("batch: 1/400 …") a slow machine prints before the error.</summary>
    private static string[] ErrorLines(string text) => [.. Lines(text).Where(l => !l.StartsWith("batch: ", StringComparison.Ordinal))];

    /// <summary>
    /// Starts a batch of the long dat into <paramref name="outDir"/> and returns once it is writing: its first
    /// file has landed in an empty folder, or (over an earlier run) the earlier index.json is gone.
    /// </summary>
    private static Process StartBatch(string dats, string outDir)
    {
        var index = Path.Combine(outDir, "index.json");
        var over = File.Exists(index);
        var process = Process.Start(BuiltCli.Start([], "batch", "--all", "--dat", dats, "--out", outDir, "--jobs", "1"))!;
        bool Writing() => over
            ? !File.Exists(index)
            : Directory.Exists(Path.Combine(outDir, "setups")) && Directory.EnumerateFiles(Path.Combine(outDir, "setups"), "*.json").Any();
        while (!process.HasExited && !Writing()) Thread.Sleep(2);
        Assert.False(process.HasExited, "the batch finished before the test could act");
        return process;
    }

    private static (int Code, string Out, string Error) Finish(Process process)
    {
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(2)))
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail("the batch did not finish in 2 minutes");
        }
        return (process.ExitCode, output.Result, error.Result);
    }

    [Fact]
    public void A_second_writer_into_a_locked_folder_is_refused_with_one_line_and_exit_6()
    {
        using var dir = new TempDir();
        using (var held = FolderLock.TryAcquire(dir.Path))
        {
            Assert.NotNull(held);
            // Another process, and another run in this one: both refused, nothing written.
            var (code, _, error) = BuiltCli.Run([], "batch", "--doors", "--out", dir.Path, "--quiet");
            Assert.Equal(6, code);
            Assert.Contains($"--out: another acshadow run is writing into {dir.Path}", Assert.Single(Lines(error), l => !l.Contains("SYNTHETIC")));
            var inProcess = CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path);
            Assert.Equal(6, inProcess.ExitCode);
            Assert.Equal([FolderLock.FileName], dir.Files());
        }
        // The lock dies with its holder: the folder is free again, and a finished run leaves no lock file.
        Assert.Equal(0, CliRun.Of("dump", "--setup", "0x020019FF", "--out", dir.Path).ExitCode);
        Assert.DoesNotContain(FolderLock.FileName, dir.Files());
    }

    [Theory]
    [InlineData("dump", "--setup", "0x020019FF")]
    [InlineData("dump", "--cell", "0xA9B40100")]
    [InlineData("view", "--setup", "0x020019FF")]
    [InlineData("chart", "--setup", "0x020019FF")]
    public void Every_folder_writer_refuses_a_folder_another_run_holds(params string[] command)
    {
        using var dir = new TempDir();
        using var held = FolderLock.TryAcquire(dir.Path);
        Assert.NotNull(held);

        var run = CliRun.Of([.. command, "--out", dir.Path]);

        Assert.Equal(6, run.ExitCode);
        // One error line (beside the notes on the synthetic sample and a Debug build), no stack trace.
        Assert.Contains($"--out: another acshadow run is writing into {dir.Path}", Assert.Single(run.ErrorLines, l => l.StartsWith("acshadow: --out", StringComparison.Ordinal)));
        Assert.DoesNotContain(run.ErrorLines, l => l.TrimStart().StartsWith("at ", StringComparison.Ordinal));
        Assert.Equal([FolderLock.FileName], dir.Files());
    }

    [Fact]
    public void A_lock_held_by_a_killed_process_is_gone_with_it()
    {
        using var dir = new TempDir();
        var dats = WriteLongDat(dir);
        var outDir = Path.Combine(dir.Path, "out");
        using (var process = StartBatch(dats, outDir))
        {
            Assert.Equal(6, CliRun.Of("dump", "--setup", "0x020019FF", "--out", outDir).ExitCode);
            process.Kill();
            process.WaitForExit();
        }
        Assert.Equal(0, CliRun.Of("batch", "--all", "--dat", dats, "--out", outDir, "--quiet").ExitCode);
    }

    [Fact]
    public void A_folder_moved_away_mid_run_fails_with_exit_6_not_a_recreated_folder()
    {
        using var dir = new TempDir();
        var dats = WriteLongDat(dir);
        var outDir = Path.Combine(dir.Path, "out");
        using var process = StartBatch(dats, outDir);
        Directory.Move(outDir, Path.Combine(dir.Path, "moved"));

        var (code, _, error) = Finish(process);

        Assert.Equal(6, code);
        var line = Assert.Single(ErrorLines(error));
        Assert.Contains(outDir, line);
        Assert.Contains("moved or deleted", line);
        Assert.False(File.Exists(Path.Combine(outDir, "index.json")));
        Assert.False(File.Exists(Path.Combine(dir.Path, "moved", "index.json")));
    }

    [Fact]
    public void A_dat_truncated_mid_run_ends_the_run_with_exit_3_and_one_line()
    {
        using var dir = new TempDir();
        var dats = WriteLongDat(dir);
        var outDir = Path.Combine(dir.Path, "out");
        using var process = StartBatch(dats, outDir);
        using (var dat = new FileStream(Path.Combine(dats, "client_portal.dat"), FileMode.Open, FileAccess.Write, FileShare.ReadWrite))
            dat.SetLength(dat.Length / 3);

        var (code, output, error) = Finish(process);

        Assert.Equal(3, code);
        var line = Assert.Single(ErrorLines(error));
        Assert.Contains("the dat changed while this run read it", line);
        Assert.DoesNotContain("skipped", output);
        Assert.False(File.Exists(Path.Combine(outDir, "index.json")));
    }

    [Fact]
    public void Ctrl_C_finishes_the_line_says_what_was_written_and_exits_130_and_verify_calls_the_folder_incomplete()
    {
        using var dir = new TempDir();
        var dats = WriteLongDat(dir);
        var outDir = Path.Combine(dir.Path, "out");
        // A finished run with other options first: an interrupted overwrite must not leave its index behind.
        Assert.Equal(0, CliRun.Of("batch", "--all", "--dat", dats, "--out", outDir, "--quiet", "--policy", "union").ExitCode);
        Assert.True(File.Exists(Path.Combine(outDir, "index.json")));
        File.Delete(Directory.GetFiles(Path.Combine(outDir, "setups"))[0]);

        using var process = StartBatch(dats, outDir);
        Assert.Equal(0, BuiltCli.RunShell([], $"kill -INT {process.Id}").ExitCode);
        var (code, _, error) = Finish(process);

        Assert.Equal(130, code);
        var line = Assert.Single(ErrorLines(error));
        Assert.Matches(@"^acshadow: interrupted: \d+ file\(s\) \(\d+ bytes\) were written to .*the folder is incomplete", line);
        Assert.DoesNotContain(Directory.GetFiles(outDir, "*", SearchOption.AllDirectories), f => f.EndsWith(".tmp", StringComparison.Ordinal));

        var verify = CliRun.Of("verify", "--fixtures", outDir, "--dat", dats);
        Assert.Equal(2, verify.ExitCode);
        Assert.Contains("an incomplete run", Assert.Single(verify.ErrorLines));
    }

    [Theory]
    [InlineData("1")]
    [InlineData("2")]
    public void Ctrl_C_during_a_chart_stops_at_once_says_what_was_written_leaves_no_temporary_and_the_next_run_completes_the_folder(string jobs)
    {
        using var dir = new TempDir();
        var dats = WriteLongDat(dir);
        var outDir = Path.Combine(dir.Path, "out");
        // A finished chart first: an interrupted run over it must not leave its tables behind to describe maps they did not chart.
        Assert.Equal(0, CliRun.Of("chart", "--setup", "0x020019FF", "--dat", dats, "--out", outDir, "--quiet").ExitCode);
        var table = Path.Combine(outDir, "chart.csv");
        Assert.True(File.Exists(table));

        // The run has charted its first object when the old tables go: no timing, only what is on disk.
        using var process = Process.Start(BuiltCli.Start([], "chart", "--all", "--dat", dats, "--out", outDir, "--jobs", jobs))!;
        while (!process.HasExited && File.Exists(table)) Thread.Sleep(2);
        Assert.False(process.HasExited, "the chart finished before the test could act");
        Assert.Equal(0, BuiltCli.RunShell([], $"kill -INT {process.Id}").ExitCode);
        var (code, _, error) = Finish(process);

        Assert.Equal(130, code);
        var line = Assert.Single(Lines(error), l => l.StartsWith("acshadow: interrupted", StringComparison.Ordinal));
        // Chart's own line when it stops at the next model; when that model takes longer than the grace a
        // signal gives (a loaded machine), the stop from outside, whose line counts the files the same way.
        var said = System.Text.RegularExpressions.Regex.Match(line,
            @"^acshadow: interrupted: (\d+) (failure map\(s\) of 400 object\(s\) were written to .*the folder is incomplete|file\(s\) \(\d+ bytes\) were written to .*each whole, and no temporary file is left)");
        Assert.True(said.Success, line);
        Assert.DoesNotContain(Lines(error), l => l.TrimStart().StartsWith("at ", StringComparison.Ordinal));
        // Only whole files: the maps it said it wrote (the earlier run's own map among them or not), no table, no temporary.
        var files = Directory.GetFiles(outDir, "*", SearchOption.AllDirectories).Select(Path.GetFileName).ToArray();
        Assert.DoesNotContain(files, f => f!.EndsWith(".tmp", StringComparison.Ordinal));
        Assert.DoesNotContain(files, f => f is "chart.csv" or "summary.csv" or "failures.csv" or "speed-accuracy.svg");
        var maps = Directory.GetFiles(outDir, "failure-map-*.svg");
        Assert.InRange(maps.Length, int.Parse(said.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture), int.Parse(said.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) + 1);
        Assert.True(int.Parse(said.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) < 400);
        foreach (var map in maps) Assert.Equal("svg", System.Xml.Linq.XDocument.Load(map).Root!.Name.LocalName);

        // verify does not take a chart folder for fixtures, and the next chart run takes the folder back as its own.
        Assert.Equal(2, CliRun.Of("verify", "--fixtures", outDir, "--dat", dats).ExitCode);
        var again = CliRun.Of("chart", "--setup", "0x020019FF", "--dat", dats, "--out", outDir, "--quiet");
        Assert.Equal(0, again.ExitCode);
        Assert.True(File.Exists(table));
        Assert.False(File.Exists(Path.Combine(outDir, FolderLock.FileName)));
    }

    [Fact]
    public void A_file_size_limit_is_exit_6_with_no_temporary_left_and_the_signal_is_not_ignored_by_the_test()
    {
        using var dir = new TempDir();
        var outDir = Path.Combine(dir.Path, "out");
        // No `trap '' XFSZ` here: acshadow itself must keep SIGXFSZ from killing it.
        var (code, _, error) = BuiltCli.RunShell([], $"ulimit -f 20; exec dotnet '{BuiltCli.Dll}' batch --doors --all --landblock 0xA9B4 --quiet --out '{outDir}'");

        Assert.Equal(6, code);
        var line = Assert.Single(Lines(error), l => !l.Contains("SYNTHETIC"));
        Assert.Contains("File too large", line);
        Assert.DoesNotContain(Directory.GetFiles(outDir, "*", SearchOption.AllDirectories), f => f.EndsWith(".tmp", StringComparison.Ordinal));
        Assert.False(File.Exists(Path.Combine(outDir, "index.json")));
    }
}
