using System.CommandLine;

namespace AcShadow.Cli.Conventions;

/// <summary>
/// "Did you mean …?" for a mistyped command or option (System.CommandLine 2.0 has no typo correction):
/// the closest name the command accepts, by edit distance, when it is close enough to be a typo.
/// </summary>
public static class TypoSuggestion
{
    public static string? For(ParseResult parse)
    {
        var word = parse.UnmatchedTokens.FirstOrDefault();
        if (word is null) return null;
        var command = parse.CommandResult.Command;
        var candidates = word.StartsWith('-')
            ? Options(parse, command).SelectMany(o => o.Aliases.Prepend(o.Name))
            : command.Subcommands.Where(c => !c.Hidden).Select(c => c.Name);
        var best = candidates.Distinct()
            .Select(c => (Name: c, Distance: Distance(word, c)))
            .Where(c => c.Distance <= Math.Max(1, word.Length / 3))
            .OrderBy(c => c.Distance).ThenBy(c => c.Name, StringComparer.Ordinal)
            .FirstOrDefault();
        return best.Name;
    }

    private static IEnumerable<Option> Options(ParseResult parse, Command command)
    {
        for (var result = parse.CommandResult; result is not null; result = result.Parent as System.CommandLine.Parsing.CommandResult)
            foreach (var o in result.Command.Options.Where(o => !o.Hidden && (result.Command == command || o.Recursive)))
                yield return o;
    }

    /// <summary>Levenshtein distance, case-insensitive.</summary>
    public static int Distance(string a, string b)
    {
        a = a.ToLowerInvariant();
        b = b.ToLowerInvariant();
        var previous = new int[b.Length + 1];
        var current = new int[b.Length + 1];
        for (var j = 0; j <= b.Length; j++) previous[j] = j;
        for (var i = 1; i <= a.Length; i++)
        {
            current[0] = i;
            for (var j = 1; j <= b.Length; j++)
                current[j] = Math.Min(Math.Min(current[j - 1] + 1, previous[j] + 1), previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1));
            (previous, current) = (current, previous);
        }
        return previous[b.Length];
    }
}
