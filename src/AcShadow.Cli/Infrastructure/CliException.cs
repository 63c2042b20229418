namespace AcShadow.Cli.Infrastructure;

/// <summary>A failure the user can fix: one line naming what was wrong and how to fix it, and an exit code.</summary>
public sealed class CliException(int exitCode, string message) : Exception(message)
{
    public int ExitCode { get; } = exitCode;
}
