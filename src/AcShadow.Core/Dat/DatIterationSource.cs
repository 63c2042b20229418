namespace AcShadow.Core.Dat;

/// <summary>Where a dat's iteration figure came from.</summary>
public enum DatIterationSource
{
    /// <summary>No Iteration record: the largest per-entry iteration in the directory.</summary>
    Directory,
    /// <summary>The Iteration record (0xFFFF0001) real dats carry.</summary>
    Record,
    /// <summary>The record is there but cannot be read: the directory's figure, as for <see cref="Directory"/>.</summary>
    UnreadableRecord,
}

public static class DatIterationSources
{
    /// <summary>The name index.json records: "record", "directory", "directory-record-unreadable".</summary>
    public static string Name(this DatIterationSource source) => source switch
    {
        DatIterationSource.Record => "record",
        DatIterationSource.UnreadableRecord => "directory-record-unreadable",
        _ => "directory",
    };

    public static bool TryParse(string? name, out DatIterationSource source)
    {
        foreach (var s in Enum.GetValues<DatIterationSource>())
            if (s.Name() == name) { source = s; return true; }
        source = DatIterationSource.Directory;
        return false;
    }

    /// <summary>What a person reads: "iteration record 0xFFFF0001", "largest directory-entry iteration (no iteration record)", ...</summary>
    public static string Describe(this DatIterationSource source) => source switch
    {
        DatIterationSource.Record => "iteration record 0xFFFF0001",
        DatIterationSource.UnreadableRecord => "largest directory-entry iteration (the iteration record 0xFFFF0001 is unreadable)",
        _ => "largest directory-entry iteration (no iteration record)",
    };
}
