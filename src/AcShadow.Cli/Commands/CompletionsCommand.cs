using System.CommandLine;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Cli.Commands;

/// <summary>
/// `acshadow completions bash|pwsh`: prints a tab-completion script. Both ask acshadow itself through
/// System.CommandLine's [suggest] directive, so they need no dotnet-suggest and always match the installed version.
/// </summary>
public static class CompletionsCommand
{
    public const string Bash = """
        # acshadow tab completion for bash: add to ~/.bashrc with  acshadow completions bash >> ~/.bashrc
        _acshadow_complete() {
            local IFS=$'\n'
            local suggestions
            suggestions=$("${COMP_WORDS[0]}" "[suggest:${COMP_POINT}]" "${COMP_LINE}" 2>/dev/null)
            COMPREPLY=( $(compgen -W "${suggestions}" -- "${COMP_WORDS[COMP_CWORD]}") )
        }
        complete -o default -F _acshadow_complete acshadow

        """;

    public const string Pwsh = """
        # acshadow tab completion for PowerShell: add to your profile with  acshadow completions pwsh >> $PROFILE
        Register-ArgumentCompleter -Native -CommandName acshadow -ScriptBlock {
            param($wordToComplete, $commandAst, $cursorPosition)
            acshadow "[suggest:$cursorPosition]" "$commandAst" 2>$null | Where-Object { $_ -like "$wordToComplete*" } | ForEach-Object {
                [System.Management.Automation.CompletionResult]::new($_, $_, 'ParameterValue', $_)
            }
        }

        """;

    public static Command Create(CliConsole console)
    {
        var shell = new Argument<string>("shell") { Description = "bash or pwsh" };
        shell.CompletionSources.Add("bash", "pwsh");
        var command = new Command("completions", "Print a tab-completion script for bash or PowerShell") { shell };
        command.SetAction(parse =>
        {
            console.Out.Write(parse.GetValue(shell) switch
            {
                "bash" => Bash.Replace("\r\n", "\n"),
                "pwsh" => Pwsh,
                var other => throw new CliException(ExitCodes.Usage, $"completions: '{other}' is not a shell: use bash or pwsh"),
            });
            return ExitCodes.Ok;
        });
        return command;
    }
}
