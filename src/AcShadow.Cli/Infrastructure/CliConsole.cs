namespace AcShadow.Cli.Infrastructure;

/// <summary>Where a command prints, and what it may assume about the terminal. Tests pass StringWriters.</summary>
public sealed record CliConsole(TextWriter Out, TextWriter Error, bool IsTerminal, Func<string, string?> Environment)
{
    public static CliConsole System() =>
        new(Console.Out, Console.Error, !Console.IsOutputRedirected && !Console.IsErrorRedirected, global::System.Environment.GetEnvironmentVariable);
}
