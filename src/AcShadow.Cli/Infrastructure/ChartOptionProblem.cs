namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// A chart or scene option the chart refuses (ChartOptions.Problem speaks of the value: "spacing must be at
/// least 0.01 m"), said as every other option error is: after the option the user typed.
/// </summary>
public static class ChartOptionProblem
{
    private static readonly (string Value, string Option)[] Options =
        [("probe radius", "--probe-radius"), ("spacing", "--spacing"), ("mover radius", "--mover-radius")];

    public static CliException Refusal(string problem) =>
        new(ExitCodes.Usage, Options.FirstOrDefault(o => problem.StartsWith(o.Value, StringComparison.Ordinal)).Option is { } option
            ? $"{option}: {problem}"
            : problem);
}
