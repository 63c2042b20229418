using System.CommandLine;
using AcShadow.Cli.Commands;
using AcShadow.Cli.Conventions;
using AcShadow.Cli.Infrastructure;
using AcShadow.Core.Dat;

namespace AcShadow.Cli;

/// <summary>
/// The command tree and the one place errors become exit codes: a usage or input problem prints one
/// line; a stack trace only with --verbose.
/// </summary>
public static class AcShadowApp
{
    public static int Run(string[] args, CliConsole console)
    {
        var verbose = new Option<bool>("--verbose") { Description = "show stack traces for errors", Recursive = true };
        var root = new RootCommand("acshadow: ground-truth collision shapes and BSP dumps from Asheron's Call dat files")
        {
            verbose,
            DumpCommand.Create(console),
        };
        foreach (var command in ExtraCommands.All(console)) root.Subcommands.Add(command);
        ExamplesHelpAction.Install(root);
        VersionAction.Install(root);

        var parse = root.Parse(args);
        if (parse.Errors.Count > 0)
        {
            // An unrecognised word says more than the "required command" error it also causes.
            var error = parse.Errors.FirstOrDefault(e => e.Message.StartsWith("Unrecognized", StringComparison.Ordinal)) ?? parse.Errors[0];
            var command = parse.CommandResult.Command;
            var help = command == root ? "acshadow --help" : $"acshadow {command.Name} --help";
            var suggestion = TypoSuggestion.For(parse) is { } near ? $" Did you mean '{near}'?" : "";
            console.Error.WriteLine($"acshadow: {error.Message}{suggestion} (see `{help}`)");
            return ExitCodes.Usage;
        }
        try
        {
            return parse.Invoke(new InvocationConfiguration { Output = console.Out, Error = console.Error, EnableDefaultExceptionHandler = false });
        }
        catch (Exception e)
        {
            var (code, message) = e switch
            {
                CliException c => (c.ExitCode, c.Message),
                DatFormatException d => (ExitCodes.DatUnreadable, $"the dat is malformed: {d.Message}"),
                _ => (ExitCodes.InternalError, $"internal error: {e.Message} (run with --verbose for the stack trace, and please report it)"),
            };
            console.Error.WriteLine($"acshadow: {message}");
            if (parse.GetValue(verbose)) console.Error.WriteLine(e.ToString());
            return code;
        }
    }
}
