using System.Diagnostics;
using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Fuzz;

/// <summary>
/// Runs one case: writes the damaged dats to a scratch folder and runs `dump` and `batch` on them through
/// the real CLI in-process (<see cref="AcShadowApp.Run"/>, output captured), on a thread a watchdog waits on.
/// A case fails on an undocumented exit code or an internal error (exit 1), on a corrupt-object message
/// without "corrupt dat" and the id, on a run past the time limit, on allocating more than the memory limit,
/// or on output that is not whole.
/// </summary>
public sealed class CaseRunner(string scratch, TimeSpan timeLimit, long memoryLimitBytes)
{
    /// <summary>0 ok, 3 dat unreadable, 4 not in dat: what a damaged dat may answer (README "Exit codes").</summary>
    private static readonly int[] Documented = [0, 3, 4];

    private const int MainThreadStack = 8 << 20; // a process's main thread: recursion limits match the CLI's

    public CaseOutcome Run(FuzzInput input, string name)
    {
        var folder = Path.Combine(scratch, name);
        Directory.CreateDirectory(folder);
        var portal = Path.Combine(folder, "client_portal.dat");
        var cell = Path.Combine(folder, "client_cell_1.dat");
        File.WriteAllBytes(portal, input.Portal);
        File.WriteAllBytes(cell, input.Cell);
        string[][] commands =
        [
            ["dump", "--setup", $"0x{input.DumpSetup:X8}", "--dat", portal, "--out", Path.Combine(folder, "dump"),
                "--policy", input.Policy, "--format", input.Format, "--verbose"],
            ["batch", "--all", "--landblock", $"0x{input.Landblock:X4}", "--dat", portal, "--cell-dat", cell,
                "--out", Path.Combine(folder, "batch"), "--jobs", "1", "--quiet", "--policy", input.Policy, "--format", input.Format, "--verbose"],
        ];

        var clock = Stopwatch.StartNew();
        var exits = new List<int>();
        CaseFailure? failure = null;
        long allocated = 0;
        var worker = new Thread(() =>
        {
            // Counted on the case's own thread (batch runs --jobs 1, so decoding happens here), so other
            // work in the process, such as tests running beside the campaign, does not count.
            var before = GC.GetAllocatedBytesForCurrentThread();
            failure = RunCommands(commands, exits);
            allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        }, MainThreadStack) { IsBackground = true, Name = name };
        worker.Start();
        var finished = worker.Join(timeLimit);
        clock.Stop();
        if (!finished)
            return new CaseOutcome(new CaseFailure($"{commands[Math.Min(exits.Count, commands.Length - 1)][0]}: hang", $"still running after {timeLimit.TotalSeconds:0.###} s"), clock.Elapsed, exits);
        if (failure is null && allocated > memoryLimitBytes)
            failure = new CaseFailure("memory", $"allocated {allocated >> 20} MiB (limit {memoryLimitBytes >> 20} MiB)");
        if (failure is null && (OutputCheck.Problem(Path.Combine(folder, "dump")) ?? OutputCheck.Problem(Path.Combine(folder, "batch"))) is { } problem)
            failure = new CaseFailure("partial output", problem);
        TryDelete(folder);
        return new CaseOutcome(failure, clock.Elapsed, exits);
    }

    private static CaseFailure? RunCommands(string[][] commands, List<int> exits)
    {
        foreach (var args in commands)
        {
            var output = new StringWriter();
            var error = new StringWriter();
            int code;
            try
            {
                code = AcShadowApp.Run(args, new CliConsole(output, error, false, _ => null));
            }
            catch (Exception e)
            {
                // AcShadowApp catches everything; reaching here means it let an exception escape.
                return new CaseFailure($"{args[0]}: escaped {e.GetType().Name}", e.ToString());
            }
            exits.Add(code);
            if (Judge(args[0], code, error.ToString()) is { } failure) return failure;
        }
        return null;
    }

    /// <summary>Why a command's exit code and stderr break the contract, or null.</summary>
    public static CaseFailure? Judge(string command, int code, string stderr)
    {
        var lines = stderr.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        var message = lines.FirstOrDefault(l => l.StartsWith("acshadow: ", StringComparison.Ordinal)
            && !l.Contains("SYNTHETIC", StringComparison.Ordinal)) ?? "";
        if (code == 1 || message.Contains("internal error", StringComparison.Ordinal))
        {
            var type = lines.Select(l => l.Trim()).FirstOrDefault(l => l.StartsWith("System.", StringComparison.Ordinal) || l.Contains("Exception:", StringComparison.Ordinal)) ?? "";
            var exception = type.Split(':')[0];
            return new CaseFailure($"{command}: internal error: {exception}", stderr);
        }
        if (!Documented.Contains(code))
            return new CaseFailure($"{command}: exit {code}", stderr);
        // A damaged object, wherever it is met, is named: "corrupt dat" and the id being read.
        // (Refusing the whole file at open, for its header or directory, names the option and the file instead.)
        var refusedAtOpen = message.StartsWith("acshadow: --dat: ", StringComparison.Ordinal)
            || message.StartsWith("acshadow: --cell-dat: ", StringComparison.Ordinal);
        if (code == 3 && !refusedAtOpen && !NamesCorruptObject(message))
            return new CaseFailure($"{command}: exit 3 without \"corrupt dat\" and an id", stderr);
        // Objects a batch skips, or parts it leaves out, because they cannot be decoded: named the same way.
        if (lines.FirstOrDefault(l => (l.Contains("unreadable:", StringComparison.Ordinal) || l.Contains("cannot be read:", StringComparison.Ordinal))
            && !NamesCorruptObject(l)) is { } unnamed)
            return new CaseFailure($"{command}: unreadable object without \"corrupt dat\" and an id", unnamed);
        return null;
    }

    private static bool NamesCorruptObject(string line) =>
        line.Contains("corrupt dat", StringComparison.Ordinal) && line.Contains("0x", StringComparison.Ordinal);

    private static void TryDelete(string folder)
    {
        try { Directory.Delete(folder, recursive: true); } catch (IOException) { } catch (UnauthorizedAccessException) { }
    }
}
