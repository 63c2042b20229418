using AcShadow.Fixtures.Json;

namespace AcShadow.Cli.Infrastructure;

/// <summary>A list of ids in a summary line: the first few and how many more, so a whole dat's list stays one readable line.</summary>
public static class IdSummary
{
    public const int Shown = 10;

    public static string Of(IReadOnlyList<uint> ids) =>
        string.Join(' ', ids.Take(Shown).Select(JsonIds.Format)) + (ids.Count > Shown ? $" … and {ids.Count - Shown} more" : "");
}
