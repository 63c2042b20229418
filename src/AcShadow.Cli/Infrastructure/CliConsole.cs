namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Where a command prints, what it may assume about the terminal, and whether the user asked it to stop
/// (Ctrl-C). Tests pass StringWriters and, to interrupt a run, a token of their own.
/// </summary>
public sealed record CliConsole(TextWriter Out, TextWriter Error, bool IsTerminal, Func<string, string?> Environment)
{
    /// <summary>Cancelled when the user presses Ctrl-C: a run stops between files, says what it wrote, exits 130.</summary>
    public CancellationToken Interrupted { get; init; }

    public static CliConsole System() =>
        new(new Infrastructure.StandardStreamWriter(() => Console.Out, isError: false), new Infrastructure.StandardStreamWriter(() => Console.Error, isError: true),
            StreamsAreTerminal(), global::System.Environment.GetEnvironmentVariable)
        {
            Interrupted = Infrastructure.Interrupt.Token,
        };

    /// <summary>A terminal on both streams; a closed or odd descriptor is "not a terminal", not a crash.</summary>
    private static bool StreamsAreTerminal()
    {
        try
        {
            return !Console.IsOutputRedirected && !Console.IsErrorRedirected;
        }
        catch (Exception e) when (e is IOException or InvalidOperationException)
        {
            return false;
        }
    }
}
