using System.Globalization;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Catalog;

/// <summary>
/// One catalog row: a door Setup, how many door weenies use it, and the MotionTables those weenies name,
/// most used first (a live door is posed by its weenie's table, not only by the Setup's own).
/// </summary>
public sealed record DoorCatalogEntry(uint SetupId, int DoorWeenies, IReadOnlyList<uint> MotionTables)
{
    public DoorCatalogEntry(uint setupId, int doorWeenies) : this(setupId, doorWeenies, []) { }
}

/// <summary>
/// The built-in door catalog: the Setup of every door weenie in the public ACE world database, kept as
/// data (Catalog/door-setups.tsv, an embedded resource whose header says where it came from) so the
/// selection `--doors` needs no network and no database.
/// </summary>
public static class DoorCatalog
{
    public const string ResourceName = "AcShadow.Core.Catalog.door-setups.tsv";

    private static readonly Lazy<IReadOnlyList<DoorCatalogEntry>> Loaded = new(() => Parse(ReadResource()));

    /// <summary>Every entry, sorted by Setup id.</summary>
    public static IReadOnlyList<DoorCatalogEntry> Entries => Loaded.Value;

    public static IReadOnlyList<uint> SetupIds => Entries.Select(e => e.SetupId).ToArray();

    private static readonly Lazy<Dictionary<uint, DoorCatalogEntry>> ById = new(() => Entries.ToDictionary(e => e.SetupId));

    /// <summary>The row of a door Setup, or null when the Setup is not a door's.</summary>
    public static DoorCatalogEntry? Find(uint setupId) => ById.Value.GetValueOrDefault(setupId);

    /// <summary>The catalog text as shipped, header comments included.</summary>
    public static string ReadResource()
    {
        using var stream = typeof(DoorCatalog).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException($"embedded resource {ResourceName} is missing from {typeof(DoorCatalog).Assembly.GetName().Name}");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }

    /// <summary>
    /// Tab-separated rows of setup_id, door_weenies and (optionally) motion_tables, a comma-separated id list;
    /// '#' lines and the column header are skipped.
    /// </summary>
    public static IReadOnlyList<DoorCatalogEntry> Parse(string text)
    {
        var entries = new List<DoorCatalogEntry>();
        var lineNumber = 0;
        foreach (var raw in text.Split('\n'))
        {
            lineNumber++;
            var line = raw.TrimEnd('\r');
            if (line.Length == 0 || line.StartsWith('#') || line.StartsWith("setup_id", StringComparison.Ordinal)) continue;
            var columns = line.Split('\t');
            if (columns.Length < 2 || !JsonIds.TryParse(columns[0], out var id)
                || !int.TryParse(columns[1], NumberStyles.None, CultureInfo.InvariantCulture, out var weenies))
                throw new FormatException($"door catalog line {lineNumber}: '{line}' is not \"setup_id<TAB>door_weenies[<TAB>motion_tables]\"");
            var tables = new List<uint>();
            foreach (var tableText in columns.Length > 2 ? columns[2].Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries) : [])
                tables.Add(JsonIds.TryParse(tableText, out var table) ? table
                    : throw new FormatException($"door catalog line {lineNumber}: motion table '{tableText}' is not a hex id"));
            entries.Add(new DoorCatalogEntry(id, weenies, tables));
        }
        return entries.OrderBy(e => e.SetupId).ToArray();
    }
}
