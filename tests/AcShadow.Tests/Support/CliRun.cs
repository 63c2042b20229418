using AcShadow.Cli;
using AcShadow.Cli.Infrastructure;

namespace AcShadow.Tests.Support;

/// <summary>Runs the acshadow CLI in-process and captures what it prints.</summary>
public sealed record CliRun(int ExitCode, string Out, string Error)
{
    public static CliRun Of(params string[] args) => With(_ => null, args);

    public static CliRun With(Func<string, string?> environment, params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var code = AcShadowApp.Run(args, new CliConsole(output, error, false, environment));
        return new CliRun(code, output.ToString(), error.ToString());
    }

    public string[] ErrorLines => Error.Split('\n', StringSplitOptions.RemoveEmptyEntries);
}
