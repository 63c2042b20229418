using System.CommandLine;
using System.Globalization;
using System.Numerics;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// What a number option accepts, and the one parser of option numbers: invariant culture whatever the
/// machine's (a comma is never a decimal point), finite, within the rule's range. A value it refuses is
/// the line "OPTION: 'TEXT' is not <see cref="What"/>: <see cref="Fix"/>"; a number past
/// <see cref="Limits"/> has its own line, saying why.
/// </summary>
public sealed record NumberRule<T>(string What, string Fix) where T : struct, INumber<T>
{
    /// <summary>The value must be greater than this (a radius, a scale).</summary>
    public T? Above { get; init; }

    /// <summary>The value must be at least this.</summary>
    public T? From { get; init; }

    /// <summary>The value must be at most this.</summary>
    public T? To { get; init; }

    /// <summary>Float by default; a whole count takes digits only (no sign, no blanks).</summary>
    public NumberStyles Styles { get; init; } = NumberStyles.Float;

    /// <summary>A range the value must also lie in, refused with "OPTION: TEXT is outside MIN-MAX: WHY".</summary>
    public (T Min, T Max, string Why)? Limits { get; init; }

    /// <summary>An option taking one such number, null when it is not given.</summary>
    public Option<T?> Option(string name, string helpName, string description) =>
        ValueOptions.Single(name, helpName, description, text => Parse(name, text));

    /// <summary>An option given once for each such number, empty when it is not given.</summary>
    public Option<T[]> Repeated(string name, string helpName, string description) =>
        ValueOptions.Repeated(name, helpName, description, text => Parse(name, text));

    public T Parse(string option, string text)
    {
        if (!T.TryParse(text, Styles, CultureInfo.InvariantCulture, out var value) || !T.IsFinite(value)
            || (Above is { } above && value <= above) || (From is { } from && value < from) || (To is { } to && value > to))
            throw new CliException(ExitCodes.Usage, $"{option}: '{text}' is not {What}: {Fix}");
        if (Limits is var (min, max, why) && (value < min || value > max))
            throw new CliException(ExitCodes.Usage, string.Create(CultureInfo.InvariantCulture, $"{option}: {text} is outside {min}-{max}: {why}"));
        return value;
    }
}
