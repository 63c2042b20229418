using System.CommandLine;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Cli.Commands;

/// <summary>Every subcommand besides dump; adding a command is one line here.</summary>
public static class ExtraCommands
{
    public static IEnumerable<Command> All(CliConsole console)
    {
        yield return BatchCommand.Create(console);
        yield return AuditCommand.Create(console);
        yield return VerifyCommand.Create(console);
        yield return ChartCommand.Create(console);
        yield return SceneCommand.Create(console);
        yield return MoveCommand.Create(console);
        yield return ViewCommand.Create(console);
        yield return DoctorCommand.Create(console);
        yield return FormatsCommand.Create(console);
        yield return CompletionsCommand.Create(console);
    }
}
