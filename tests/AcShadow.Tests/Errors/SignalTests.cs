using System.Diagnostics;
using System.Runtime.InteropServices;
using AcShadow.Files;
using AcShadow.Tests.Support;

namespace AcShadow.Tests.Errors;

/// <summary>
/// Issue 32 item 12: Ctrl-C (SIGINT) and SIGTERM sent to the built acshadow as a real process, in commands
/// that used not to hear them (audit --chart ran 134 s on; doctor never checked; scene only after its compile)
/// or said "nothing was written" after writing files, or left chart.csv.PID.tmp behind. Each must exit 130
/// (SIGINT) or 143 (SIGTERM) with one line that says truthfully what is on disk, and leave no temporary
/// file. The signal is sent once the process has shown it is running; how fast it stops is not asserted.
/// </summary>
public class SignalTests
{
    private const int SigInt = 2;
    private const int SigTerm = 15;

    [DllImport("libc", SetLastError = true, EntryPoint = "kill")]
    private static extern int SendSignal(int pid, int signal);

    [DllImport("libc", SetLastError = true, EntryPoint = "mkfifo")]
    private static extern int MakeFifo(string path, uint mode);

    /// <summary>Starts acshadow, waits for its first line on stderr (the dat is being opened), sends the signal, and waits for the end.</summary>
    private static (int ExitCode, string[] ErrorLines) SignalWhileRunning(int signal, params string[] args) =>
        SignalWhenReady(signal, null, args);

    /// <summary>
    /// As <see cref="SignalWhileRunning"/>, but the process is known to be running once acshadow opens the pipe
    /// <paramref name="setupList"/> to read it: the test holds the writing end open, so the read waits.
    /// </summary>
    private static (int ExitCode, string[] ErrorLines) SignalWhenReady(int signal, string? setupList, params string[] args)
    {
        using var process = Process.Start(BuiltCli.Start([], args))!;
        var output = process.StandardOutput.ReadToEndAsync();
        string? first = null;
        FileStream? writer = null;
        if (setupList is null)
        {
            first = process.StandardError.ReadLine();
            Assert.False(first is null, $"acshadow {string.Join(' ', args)} ended before it said anything");
        }
        else
        {
            // Opening a pipe's writing end waits for its reader: then acshadow is reading it.
            var opened = Task.Run(() => new FileStream(setupList, FileMode.Open, FileAccess.Write));
            while (!opened.Wait(TimeSpan.FromMilliseconds(50))) Assert.False(process.HasExited, "the command ended before it read its setup list");
            writer = opened.Result;
        }
        Assert.False(process.HasExited, "the command finished before the signal could be sent");
        Assert.Equal(0, SendSignal(process.Id, signal));
        var rest = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(2)))
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"acshadow {string.Join(' ', args)} went on for 2 minutes after the signal");
        }
        writer?.Dispose();
        _ = output.Result;
        var lines = (first is null ? [] : new[] { first }).Concat(rest.Result.Split('\n', StringSplitOptions.RemoveEmptyEntries)).ToArray();
        return (process.ExitCode, lines);
    }

    private static string FinalLine(string[] lines) =>
        Assert.Single(lines, l => l.StartsWith("acshadow: interrupted", StringComparison.Ordinal) || l.StartsWith("acshadow: terminated", StringComparison.Ordinal));

    private static string[] Files(string folder) =>
        Directory.Exists(folder) ? Directory.GetFiles(folder, "*", SearchOption.AllDirectories) : [];

    /// <summary>No temporary left, and "nothing was written" only when nothing (but the lock's file) is there.</summary>
    private static void AssertTruthful(string folder, string line)
    {
        var files = Files(folder);
        Assert.DoesNotContain(files, f => f.EndsWith(AtomicFile.TemporarySuffix, StringComparison.Ordinal));
        var output = files.Where(f => Path.GetFileName(f) != FolderLock.FileName).ToArray();
        if (line.EndsWith("nothing was written", StringComparison.Ordinal)) Assert.Empty(output);
        // The command's own account (chart counts its failure maps, the only files it writes before its CSVs)
        // or, when it had not stopped by itself, the forced stop's count of whole files.
        else if (line.Contains(" failure map(s) ", StringComparison.Ordinal)) Assert.Contains($": {output.Length} failure map(s) ", line);
        else Assert.Contains($"{output.Length} file(s)", line);
    }

    [Fact]
    public void Audit_with_chart_hears_ctrl_c_and_exits_130()
    {
        var (code, lines) = SignalWhileRunning(SigInt, "audit", "--all", "--chart", "--jobs", "1");
        Assert.Equal(130, code);
        Assert.Equal("acshadow: interrupted: nothing was written", FinalLine(lines));
    }

    [Fact]
    public void Scene_hears_sigterm_during_its_compile_exits_143_and_leaves_no_temporary()
    {
        using var dir = new TempDir();
        var outDir = Path.Combine(dir.Path, "scene");
        var (code, lines) = SignalWhileRunning(SigTerm, "scene", "--landblock", "0xA9B4", "--spacing", "0.02", "--out", outDir, "--quiet");
        Assert.Equal(143, code);
        var line = FinalLine(lines);
        Assert.StartsWith("acshadow: terminated (SIGTERM): ", line);
        AssertTruthful(outDir, line);
    }

    [Fact]
    public void Chart_hears_sigterm_and_leaves_no_chart_csv_temporary()
    {
        using var dir = new TempDir();
        var outDir = Path.Combine(dir.Path, "chart");
        var (code, lines) = SignalWhileRunning(SigTerm, "chart", "--all", "--spacing", "0.02", "--out", outDir, "--quiet", "--jobs", "1");
        Assert.Equal(143, code);
        var line = FinalLine(lines);
        Assert.StartsWith("acshadow: terminated (SIGTERM): ", line);
        AssertTruthful(outDir, line);
    }

    [Fact]
    public void Doctor_blocked_writing_its_report_hears_ctrl_c()
    {
        using var dir = new TempDir();
        var fifo = Path.Combine(dir.Path, "report.json");
        Assert.Equal(0, MakeFifo(fifo, Convert.ToUInt32("600", 8)));
        // No reader ever opens the pipe: doctor checks the dat, then waits to write for as long as it is let.
        var (code, lines) = SignalWhileRunning(SigInt, "doctor", "--out", fifo);
        Assert.Equal(130, code);
        Assert.Equal("acshadow: interrupted: nothing was written", FinalLine(lines));
        Assert.DoesNotContain(Files(dir.Path), f => f.EndsWith(AtomicFile.TemporarySuffix, StringComparison.Ordinal));
    }

    [Fact]
    public void Batch_waiting_for_its_setup_list_hears_sigterm()
    {
        using var dir = new TempDir();
        var fifo = Path.Combine(dir.Path, "setups.txt");
        Assert.Equal(0, MakeFifo(fifo, Convert.ToUInt32("600", 8)));
        var outDir = Path.Combine(dir.Path, "batch");
        var (code, lines) = SignalWhenReady(SigTerm, fifo, "batch", "--setups", fifo, "--out", outDir, "--quiet");
        Assert.Equal(143, code);
        var line = FinalLine(lines);
        Assert.Equal("acshadow: terminated (SIGTERM): nothing was written", line);
        AssertTruthful(outDir, line);
    }

    /// <summary>
    /// view used to end "interrupted: nothing was written" after writing 258 files. In-process, Ctrl-C is its
    /// token, cancelled as soon as the first file is reported written: the line counts that file.
    /// </summary>
    [Fact]
    public void View_interrupted_after_writing_says_how_many_files_it_wrote()
    {
        using var dir = new TempDir();
        var outDir = Path.Combine(dir.Path, "view");
        using var interrupt = new CancellationTokenSource();
        var output = new CancelOnWrite(interrupt);
        var error = new StringWriter();
        var code = AcShadow.Cli.AcShadowApp.Run(["view", "--landblock", "0xA9B4", "--out", outDir],
            new AcShadow.Cli.Infrastructure.CliConsole(output, error, false, _ => null) { Interrupted = interrupt.Token });
        Assert.Equal(130, code);
        var line = FinalLine(error.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries));
        Assert.StartsWith("acshadow: interrupted: 1 file(s) (", line);
        AssertTruthful(outDir, line);
    }

    /// <summary>Standard output that cancels the run's token when a command reports its first written file.</summary>
    private sealed class CancelOnWrite(CancellationTokenSource interrupt) : StringWriter
    {
        public override void WriteLine(string? value)
        {
            base.WriteLine(value);
            if (value?.StartsWith("wrote ", StringComparison.Ordinal) == true) interrupt.Cancel();
        }
    }
}
