namespace AcShadow.Core.Export;

/// <summary>Which part of a selection asked for a Setup (an id can come from several).</summary>
[Flags]
public enum SelectionSource
{
    None = 0,
    Doors = 0x1,
    All = 0x2,
    SetupsFile = 0x4,
    Landblock = 0x8,
}

public static class SelectionSources
{
    /// <summary>The names used in index.json and messages: doors, all, setups-file, landblock.</summary>
    public static IReadOnlyList<string> Names(this SelectionSource sources)
    {
        var names = new List<string>();
        if (sources.HasFlag(SelectionSource.Doors)) names.Add("doors");
        if (sources.HasFlag(SelectionSource.All)) names.Add("all");
        if (sources.HasFlag(SelectionSource.SetupsFile)) names.Add("setups-file");
        if (sources.HasFlag(SelectionSource.Landblock)) names.Add("landblock");
        return names;
    }
}
