namespace AcShadow.Cli.Infrastructure;

/// <summary>Documented process exit codes (README "Exit codes").</summary>
public static class ExitCodes
{
    public const int Ok = 0;
    public const int InternalError = 1;
    public const int Usage = 2;
    public const int DatUnreadable = 3;
    public const int NotInDat = 4;
    public const int Drift = 5;
    public const int OutputFailed = 6;
    /// <summary>Ctrl-C (SIGINT): 128 + 2, as a shell reports a process the signal ended.</summary>
    public const int Interrupted = 130;
    /// <summary>SIGTERM: 128 + 15.</summary>
    public const int Terminated = 143;
}
