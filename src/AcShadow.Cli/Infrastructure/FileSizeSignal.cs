using System.Runtime.InteropServices;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// A write past the file-size limit (ulimit -f) raises SIGXFSZ, whose default action kills the process
/// mid-file with a temporary file left behind. Handled (and its default action cancelled), the write fails
/// with EFBIG instead, which the output writer reports as "cannot write FILE: File too large" (exit 6)
/// after removing its temporary.
/// </summary>
public static class FileSizeSignal
{
    // SIGXFSZ is 25 on Linux (x86, ARM) and macOS; .NET takes raw signal numbers cast to PosixSignal.
    private const int SigXfsz = 25;
    private static PosixSignalRegistration? _registration;

    public static void Handle()
    {
        if (!(OperatingSystem.IsLinux() || OperatingSystem.IsMacOS())) return;
        _registration ??= PosixSignalRegistration.Create((PosixSignal)SigXfsz, context => context.Cancel = true);
    }
}
