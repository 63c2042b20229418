using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

try
{
    FileSizeSignal.Handle();
    Interrupt.Install();
    return AcShadowApp.Run(args, CliConsole.System());
}
// What escapes the command's own handling happens before or around it: the runtime failing to load
// acshadow's own assemblies (no file descriptors left, a broken install). One line, never a stack trace.
catch (Exception e)
{
    try
    {
        Console.Error.WriteLine($"acshadow: {AcShadowApp.Describe(e)}");
    }
    catch (Exception)
    {
    }
    return ExitCodes.InternalError;
}
