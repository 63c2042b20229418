using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

FileSizeSignal.Handle();
Interrupt.Install();
return AcShadowApp.Run(args, CliConsole.System());
