namespace AcShadow.Fixtures.Batch;

/// <summary>The names index.json gives a <see cref="FixtureKind"/>.</summary>
public static class FixtureKinds
{
    public static string Name(this FixtureKind kind) => kind switch
    {
        FixtureKind.Shadow => "shadow",
        FixtureKind.Bsp => "bsp",
        FixtureKind.Scene => "scene",
        FixtureKind.AcdreamGfxObj => "acdream",
        FixtureKind.Cell => "cell",
        FixtureKind.AcdreamCell => "acdream-cell",
        _ => throw new ArgumentOutOfRangeException(nameof(kind)),
    };

    public static bool TryParse(string? name, out FixtureKind kind)
    {
        foreach (var k in Enum.GetValues<FixtureKind>())
        {
            if (k.Name() != name) continue;
            kind = k;
            return true;
        }
        kind = default;
        return false;
    }
}
