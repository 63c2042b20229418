using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

return AcShadowApp.Run(args, CliConsole.System());
