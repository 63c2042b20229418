using AcShadow.Cli;

return AcShadowApp.Run(args, CliConsole.System());
