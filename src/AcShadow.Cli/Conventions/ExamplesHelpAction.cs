using System.CommandLine;
using System.CommandLine.Help;
using System.CommandLine.Invocation;

namespace AcShadow.Cli.Conventions;

/// <summary>System.CommandLine's help, followed by the command's examples (<see cref="CommandExamples"/>).</summary>
public sealed class ExamplesHelpAction(HelpAction help) : SynchronousCommandLineAction
{
    /// <summary>Like the built-in help: `acshadow verify --help` shows help, not "--fixtures is required".</summary>
    public override bool ClearsParseErrors => true;

    public override int Invoke(ParseResult parseResult)
    {
        var code = help.Invoke(parseResult);
        var command = parseResult.CommandResult.Command;
        if (CommandExamples.ByCommand.TryGetValue(command is RootCommand ? "acshadow" : command.Name, out var examples))
        {
            var output = parseResult.InvocationConfiguration.Output;
            output.WriteLine("Examples:");
            foreach (var example in examples) output.WriteLine($"  {example}");
            output.WriteLine();
        }
        return code;
    }

    /// <summary>Puts the examples under every command's --help (the help option is recursive from the root).</summary>
    public static void Install(RootCommand root)
    {
        var option = root.Options.OfType<HelpOption>().Single();
        if (option.Action is HelpAction help) option.Action = new ExamplesHelpAction(help);
    }
}
