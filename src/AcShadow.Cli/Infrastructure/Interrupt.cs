using System.Runtime.InteropServices;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Ctrl-C (SIGINT) and SIGTERM as a user sees them: the first asks the run to stop (a command that checks
/// between files finishes its progress line, says what it wrote and exits 130, or 143 for SIGTERM). A command
/// busy in work that does not check (an audit's chart, a doctor's decode, a scene's compile) is stopped by
/// <see cref="StopGrace"/> later all the same: no new file starts, unfinished temporaries are removed, the
/// run's <see cref="OutputLedger"/> says what is on disk, and the process exits with the same code. A second
/// signal does that at once.
/// </summary>
public static class Interrupt
{
    /// <summary>How long a command has to stop by itself after the first signal, so the signal is heard within a second.</summary>
    public static readonly TimeSpan StopGrace = TimeSpan.FromMilliseconds(750);

    /// <summary>How long writes in flight get to end whole once the run is stopped from outside.</summary>
    private static readonly TimeSpan WriteGrace = TimeSpan.FromMilliseconds(250);

    private static readonly CancellationTokenSource Source = new();
    private static readonly List<PosixSignalRegistration> Registrations = [];
    private static PosixSignal? _signal;
    private static OutputLedger? _ledger;
    private static Timer? _stopTimer;
    private static int _reported;

    public static CancellationToken Token => Source.Token;

    /// <summary>130 after Ctrl-C (and in-process runs cancelled by their own token), 143 after SIGTERM: 128 + the signal.</summary>
    public static int ExitCode => _signal == PosixSignal.SIGTERM ? ExitCodes.Terminated : ExitCodes.Interrupted;

    /// <summary>The first word of the line an interrupted run ends with.</summary>
    public static string Word => _signal == PosixSignal.SIGTERM ? "terminated (SIGTERM)" : "interrupted";

    /// <summary>Installs the handlers (once, for the process; tests running commands in-process do not).</summary>
    public static void Install()
    {
        if (Registrations.Count > 0) return;
        Registrations.Add(PosixSignalRegistration.Create(PosixSignal.SIGINT, Heard));
        Registrations.Add(PosixSignalRegistration.Create(PosixSignal.SIGTERM, Heard));
    }

    /// <summary>The ledger of the run a forced stop reports on (the process's one run).</summary>
    public static void Watch(OutputLedger ledger)
    {
        if (Registrations.Count > 0) _ledger = ledger;
    }

    /// <summary>
    /// Whether this caller is the one to print the interrupted line: the command's own way out and the forced
    /// stop may race, and exactly one line is printed.
    /// </summary>
    public static bool ClaimReport() => Registrations.Count == 0 || Interlocked.Exchange(ref _reported, 1) == 0;

    private static void Heard(PosixSignalContext context)
    {
        context.Cancel = true;
        if (Source.IsCancellationRequested)
        {
            ForceStop(null);
            return;
        }
        _signal = context.Signal;
        Source.Cancel();
        _stopTimer = new Timer(ForceStop, null, StopGrace, Timeout.InfiniteTimeSpan);
    }

    /// <summary>The command did not stop by itself: stop its writing, say what is on disk, end the process.</summary>
    private static void ForceStop(object? state)
    {
        if (!ClaimReport()) return;
        var ledger = _ledger;
        ledger?.Close(WriteGrace);
        RawStandardError.WriteLine($"acshadow: {Word}: {ledger?.Summary() ?? "nothing was written"}");
        Environment.Exit(ExitCode);
    }
}
