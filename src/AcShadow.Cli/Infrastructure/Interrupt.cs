using System.Runtime.InteropServices;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Ctrl-C as a user sees it: the first SIGINT asks the run to stop (it finishes the progress line, says
/// what it wrote and exits 130); a second one ends the process at once, as usual.
/// </summary>
public static class Interrupt
{
    private static readonly CancellationTokenSource Source = new();
    private static PosixSignalRegistration? _registration;

    public static CancellationToken Token => Source.Token;

    /// <summary>Installs the handler (once, for the process; tests running commands in-process do not).</summary>
    public static void Install()
    {
        _registration ??= PosixSignalRegistration.Create(PosixSignal.SIGINT, context =>
        {
            if (Source.IsCancellationRequested) return;
            context.Cancel = true;
            Source.Cancel();
        });
    }
}
