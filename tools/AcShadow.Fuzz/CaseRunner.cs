using System.Diagnostics;
using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Fuzz;

/// <summary>
/// Runs one case: writes the damaged dats to a scratch folder and runs `dump` and `batch` on them through
/// the real CLI in-process (<see cref="AcShadowApp.Run"/>, output captured), on a thread a watchdog waits
/// on; a deep case also runs `chart` (the dumped Setup on a coarse grid) and `verify`, which reads the
/// batch's fixtures after one byte of one of them is damaged too, so it meets mutated fixtures as well as
/// a mutated dat; then, when the batch succeeded, the same `batch --incremental` again, after which
/// `verify` must pass: a re-run repairs any damaged file (reuse checks content, not size).
/// A case fails on an undocumented exit code or an internal error (exit 1), on a corrupt-object message
/// without "corrupt dat" and the id, on a run past the time limit, on allocating more than the memory limit,
/// or on output that is not whole, or when the commands disagree about a refused dat (one damage, one answer:
/// a refused portal dat is refused with the same line by every command that reads the damage; batch reads the
/// whole directory, dump and chart the paths their lookups take).
/// </summary>
public sealed class CaseRunner(string scratch, TimeSpan timeLimit, long memoryLimitBytes)
{
    /// <summary>0 ok, 3 dat unreadable, 4 not in dat: what a damaged dat may answer (docs/errors.md).</summary>
    private static readonly int[] Documented = [0, 3, 4];

    /// <summary>verify may also find a bad fixtures folder (2) or drift (5): its fixtures are damaged on purpose.</summary>
    private static readonly int[] DocumentedForVerify = [0, 2, 3, 4, 5];

    private const int MainThreadStack = 8 << 20; // a process's main thread: recursion limits match the CLI's

    /// <summary>Grid spacing of a deep case's chart (metres): coarse, since what a case fuzzes is chart reading
    /// the damaged Setup and its parts, not the density of its grid.</summary>
    public const string ChartSpacing = "4";

    public CaseOutcome Run(FuzzInput input, string name, bool deep = true)
    {
        var folder = Path.Combine(scratch, name);
        Directory.CreateDirectory(folder);
        var portal = Path.Combine(folder, "client_portal.dat");
        var cell = Path.Combine(folder, "client_cell_1.dat");
        File.WriteAllBytes(portal, input.Portal);
        File.WriteAllBytes(cell, input.Cell);
        var batchFolder = Path.Combine(folder, "batch");
        string[][] all =
        [
            ["dump", "--setup", $"0x{input.DumpSetup:X8}", "--dat", portal, "--out", Path.Combine(folder, "dump"),
                "--policy", input.Policy, "--format", input.Format, "--verbose"],
            ["batch", "--all", "--landblock", $"0x{input.Landblock:X4}", "--dat", portal, "--cell-dat", cell,
                "--out", batchFolder, "--jobs", "1", "--quiet", "--policy", input.Policy, "--format", input.Format, "--incremental", "--verbose"],
            ["chart", "--setup", $"0x{input.DumpSetup:X8}", "--dat", portal, "--out", Path.Combine(folder, "chart"), "--spacing", ChartSpacing, "--quiet", "--verbose"],
            ["verify", "--fixtures", batchFolder, "--dat", portal, "--cell-dat", cell, "--jobs", "1", "--verbose"],
        ];
        var commands = deep ? all : all[..2];
        var times = new Dictionary<string, TimeSpan>(StringComparer.Ordinal);

        var clock = Stopwatch.StartNew();
        var exits = new List<int>();
        CaseFailure? failure = null;
        string? damaged = null;
        long allocated = 0;
        var worker = new Thread(() =>
        {
            // Counted on the case's own thread (batch runs --jobs 1, so decoding happens here), so other
            // work in the process, such as tests running beside the campaign, does not count.
            var before = GC.GetAllocatedBytesForCurrentThread();
            failure = RunCommands(commands, exits, times, () =>
            {
                // The batch's output is judged whole before one of its files is damaged for verify.
                if (OutputCheck.Problem(batchFolder) is { } partial) return new CaseFailure("partial output", partial);
                damaged = DamageOneFixture(batchFolder, input.DumpSetup);
                return null;
            });
            if (failure is null && deep && exits.Count == commands.Length && exits[1] == 0)
                failure = Repair(commands[1], commands[3], damaged, times);
            allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        }, MainThreadStack) { IsBackground = true, Name = name };
        worker.Start();
        var finished = worker.Join(timeLimit);
        clock.Stop();
        if (!finished)
            return new CaseOutcome(new CaseFailure($"{commands[Math.Min(exits.Count, commands.Length - 1)][0]}: hang", $"still running after {timeLimit.TotalSeconds:0.###} s"), clock.Elapsed, exits.ToArray());
        if (failure is null && allocated > memoryLimitBytes)
            failure = new CaseFailure("memory", $"allocated {allocated >> 20} MiB (limit {memoryLimitBytes >> 20} MiB)");
        if (failure is null && OutputCheck.Problem(Path.Combine(folder, "dump")) is { } problem)
            failure = new CaseFailure("partial output", problem);
        TryDelete(folder);
        return new CaseOutcome(failure, clock.Elapsed, exits) { CommandTimes = times };
    }

    private static CaseFailure? RunCommands(string[][] commands, List<int> exits, Dictionary<string, TimeSpan> times, Func<CaseFailure?> beforeVerify)
    {
        var refusals = new Dictionary<string, string?>(StringComparer.Ordinal);
        foreach (var args in commands)
        {
            if (args[0] == "verify" && beforeVerify() is { } partial) return partial;
            var output = new StringWriter();
            var error = new StringWriter();
            int code;
            var started = Stopwatch.GetTimestamp();
            try
            {
                code = AcShadowApp.Run(args, new CliConsole(output, error, false, _ => null));
            }
            catch (Exception e)
            {
                // AcShadowApp catches everything; reaching here means it let an exception escape.
                return new CaseFailure($"{args[0]}: escaped {e.GetType().Name}", e.ToString());
            }
            finally
            {
                lock (times) times[args[0]] = Stopwatch.GetElapsedTime(started);
            }
            exits.Add(code);
            if (Judge(args[0], code, error.ToString()) is { } failure) return failure;
            if (Disagreement(refusals, args[0], error.ToString()) is { } disagreement) return disagreement;
        }
        return null;
    }

    /// <summary>
    /// The batch again over its damaged folder, then verify, which must now pass: the byte verify was shown
    /// damaged keeps the file's size, so only a reuse that checks content (SHA-256) writes it again. The one
    /// refusal allowed: a file no index lists (index.json, incremental.json) whose first line the damage hit
    /// no longer reads as acshadow's, so the batch will not replace it (docs/errors.md, exit 6).
    /// </summary>
    private static CaseFailure? Repair(string[] batch, string[] verify, string? damaged, Dictionary<string, TimeSpan> times)
    {
        foreach (var args in new[] { batch, verify })
        {
            var output = new StringWriter();
            var error = new StringWriter();
            var started = Stopwatch.GetTimestamp();
            var code = AcShadowApp.Run(args, new CliConsole(output, error, false, _ => null));
            lock (times) times[args[0] + " (re-run)"] = Stopwatch.GetElapsedTime(started);
            if (code == 6 && args == batch && damaged is not null && error.ToString().Contains($"--out: {damaged} would be replaced but is not acshadow output", StringComparison.Ordinal))
                return null;
            if (code != 0)
                return new CaseFailure($"{args[0]} after an incremental re-run: exit {code}", $"{output}\n{error}\n(the damaged fixture: {damaged ?? "none"})");
        }
        return null;
    }

    /// <summary>
    /// The line a command refused the portal dat with; a second command that refuses the same dat with another
    /// line, or opens a dat a lookup refused, is a failure (the dat layer decides damage one way). Only batch
    /// lists ids (it walks the whole directory at open); dump and chart read the directory a path at a time,
    /// so they may open a dat whose damage lies off their paths, which batch refuses.
    /// </summary>
    private static CaseFailure? Disagreement(Dictionary<string, string?> refusals, string command, string stderr)
    {
        if (command == "verify") return null; // its fixtures are damaged on purpose: it may stop on them first
        var line = stderr.Split('\n').FirstOrDefault(l => l.StartsWith("acshadow: --dat: ", StringComparison.Ordinal));
        refusals[command] = line;
        foreach (var (other, otherLine) in refusals)
        {
            if (other == command || otherLine == line) continue;
            if (OffItsPaths(other, otherLine, command, line) || OffItsPaths(command, line, other, otherLine)) continue;
            return new CaseFailure($"{other} and {command} disagree about the dat", $"{other}: {otherLine ?? "(opened it)"}\n{command}: {line ?? "(opened it)"}");
        }
        return null;
    }

    /// <summary>A lookup command opened the dat the listing command (batch) refused.</summary>
    private static bool OffItsPaths(string lookup, string? lookupLine, string listing, string? listingLine) =>
        lookup != "batch" && lookupLine is null && listing == "batch" && listingLine is not null;

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
        if (!(command == "verify" ? DocumentedForVerify : Documented).Contains(code))
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

    /// <summary>Flips one byte of one file the batch wrote (chosen by the case's seed): its path, or null when it wrote nothing.</summary>
    private static string? DamageOneFixture(string batchFolder, uint seed)
    {
        if (!Directory.Exists(batchFolder)) return null;
        var files = Directory.GetFiles(batchFolder, "*.json", SearchOption.AllDirectories).Order(StringComparer.Ordinal).ToArray();
        if (files.Length == 0) return null;
        var file = files[(int)(seed % (uint)files.Length)];
        var bytes = File.ReadAllBytes(file);
        if (bytes.Length == 0) return null;
        bytes[(int)(seed / 7 % (uint)bytes.Length)] ^= (byte)(1 + seed % 255);
        File.WriteAllBytes(file, bytes);
        return file;
    }

    private static bool NamesCorruptObject(string line) =>
        line.Contains("corrupt dat", StringComparison.Ordinal) && line.Contains("0x", StringComparison.Ordinal);

    private static void TryDelete(string folder)
    {
        try { Directory.Delete(folder, recursive: true); } catch (IOException) { } catch (UnauthorizedAccessException) { }
    }
}
