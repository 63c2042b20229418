using System.CommandLine;
using System.CommandLine.Parsing;
using System.Runtime.CompilerServices;
using System.Runtime.ExceptionServices;

namespace AcShadow.Cli.Infrastructure;

/// <summary>
/// Options declared with their value's type and its parser, once. The text is parsed while the command
/// line is; a bad value becomes a parse error that keeps the one usage line its parser wrote
/// (a <see cref="CliException"/>, exit 2). <see cref="AcShadowApp"/> reports that line as it reports a
/// command's own usage errors (<see cref="Refusal"/>), not as System.CommandLine's errors, which point at the help.
/// </summary>
public static class ValueOptions
{
    /// <summary>A bad value's line, by the parse result its error names; the table lets go of a parse result no one holds.</summary>
    private static readonly ConditionalWeakTable<SymbolResult, CliException> Refusals = new();

    /// <summary>An option taking one value, null when it is not given.</summary>
    public static Option<T?> Single<T>(string name, string helpName, string description, Func<string, T> parse) where T : struct =>
        WithoutEnumNames(new Option<T?>(name)
        {
            Description = description,
            HelpName = helpName,
            CustomParser = result => TryParse(result, result.Tokens[0].Value, parse, out var value) ? value : null,
        });

    /// <summary>An option given once for each value (--setup A --setup B), empty when it is not given.</summary>
    public static Option<T[]> Repeated<T>(string name, string helpName, string description, Func<string, T> parse) =>
        WithoutEnumNames(new Option<T[]>(name)
        {
            Description = description,
            HelpName = helpName,
            CustomParser = result =>
            {
                var values = new T[result.Tokens.Count];
                for (var i = 0; i < values.Length; i++)
                    if (!TryParse(result, result.Tokens[i].Value, parse, out values[i])) return [];
                return values;
            },
        });

    /// <summary>An option whose text is its value once <paramref name="check"/> accepts it (it may return it changed).</summary>
    public static Option<string?> Text(string name, string helpName, string description, Func<string, string> check) =>
        new(name)
        {
            Description = description,
            HelpName = helpName,
            CustomParser = result => TryParse(result, result.Tokens[0].Value, check, out var value) ? value : null,
        };

    /// <summary>
    /// The first bad value's error, when bad values are all the command line has wrong (System.CommandLine's
    /// own errors, an unknown option say, are reported first and as before); null when there is none.
    /// </summary>
    public static ExceptionDispatchInfo? Refusal(ParseResult parse)
    {
        if (parse.Errors.Any(e => !IsRefusal(e))) return null;
        return parse.Errors.Select(e => Refusals.TryGetValue(e.SymbolResult!, out var refused) ? ExceptionDispatchInfo.Capture(refused) : null).FirstOrDefault();
    }

    /// <summary>Whether the error is a bad value one of these options' parsers refused.</summary>
    public static bool IsRefusal(ParseError error) => error.SymbolResult is { } symbol && Refusals.TryGetValue(symbol, out _);

    private static bool TryParse<T>(ArgumentResult result, string text, Func<string, T> parse, out T value)
    {
        try
        {
            value = parse(text);
            return true;
        }
        catch (CliException e) when (e.ExitCode == ExitCodes.Usage)
        {
            // The error names the option's result (the argument's, for an option's own value); either finds the line.
            Refusals.AddOrUpdate(result, e);
            if (result.Parent is { } option) Refusals.AddOrUpdate(option, e);
            result.AddError(e.Message);
            value = default!;
            return false;
        }
    }

    /// <summary>System.CommandLine completes an enum-typed value with its C# names; these options complete as they did as text.</summary>
    private static Option<T> WithoutEnumNames<T>(Option<T> option)
    {
        option.CompletionSources.Clear();
        return option;
    }
}
