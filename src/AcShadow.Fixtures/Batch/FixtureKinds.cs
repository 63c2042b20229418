using AcShadow.Fixtures.Formats;

namespace AcShadow.Fixtures.Batch;

/// <summary>The names index.json gives a <see cref="FixtureKind"/>: its format's short name.</summary>
internal static class FixtureKinds
{
    public static string Name(this FixtureKind kind) => kind.Format().Name;

    internal static FileFormat Format(this FixtureKind kind) => kind switch
    {
        FixtureKind.Shadow => FileFormats.Shadow,
        FixtureKind.Bsp => FileFormats.Bsp,
        FixtureKind.Scene => FileFormats.Scene,
        FixtureKind.AcdreamGfxObj => FileFormats.AcdreamGfxObj,
        FixtureKind.Cell => FileFormats.Cell,
        FixtureKind.AcdreamCell => FileFormats.AcdreamCell,
        FixtureKind.Movement => FileFormats.Movement,
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
