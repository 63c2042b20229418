using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

// Before any assembly beyond CoreLib is needed: with too few descriptors, later steps fail unpredictably.
if (DescriptorLimit.Problem() is { } tooFew)
{
    RawStandardError.WriteLine(tooFew);
    return ExitCodes.InternalError;
}
// Under `ulimit -v` the runtime's defaults do not fit: a child with settings that do runs the command.
if (VirtualMemoryLimit.RunLimitedChild(args) is { } childExit) return childExit;
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
    var line = $"acshadow: {AcShadowApp.CannotLoad}: {AcShadowApp.CannotLoadCause}";
    try
    {
        line = $"acshadow: {AcShadowApp.Describe(e)}";
        Report(line);
    }
    catch (Exception)
    {
        RawStandardError.WriteLine(line);
    }
    return ExitCodes.InternalError;
}

// Its own method so that compiling Main needs no System.Console: with few descriptors that assembly may not
// load, and then it is this call that fails, inside the try above.
static void Report(string line) => Console.Error.WriteLine(line);
