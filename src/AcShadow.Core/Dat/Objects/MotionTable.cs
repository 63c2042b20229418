using AcShadow.Core.Dat.Binary;
namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A MotionTable (0x09xxxxxx): which motion a style starts in and what each (style, motion) plays.
/// Layout (DatReaderWriter dats.xml MotionTable; ACE DatLoader MotionTable.Unpack; retail CMotionTable::UnPack):
/// Id, DefaultStyle, then four counted maps: StyleDefaults (style → default substate), Cycles and Modifiers
/// (key → MotionData, key = <see cref="MotionCommand.Key"/>), Links (key of (style, from) → counted map of
/// to-motion → MotionData). Maps keep the dat's order, so a table is written back byte for byte.
/// </summary>
public sealed record MotionTable(
    uint Id,
    uint DefaultStyle,
    IReadOnlyList<KeyValuePair<uint, uint>> StyleDefaults,
    IReadOnlyList<KeyValuePair<uint, MotionData>> Cycles,
    IReadOnlyList<KeyValuePair<uint, MotionData>> Modifiers,
    IReadOnlyList<KeyValuePair<uint, IReadOnlyList<KeyValuePair<uint, MotionData>>>> Links)
{
    private Dictionary<uint, uint>? _styleDefaults;
    private Dictionary<uint, MotionData>? _cycles;
    private Dictionary<uint, Dictionary<uint, MotionData>>? _links;

    public bool TryGetStyleDefault(uint style, out uint substate) =>
        (_styleDefaults ??= StyleDefaults.ToDictionary(p => p.Key, p => p.Value)).TryGetValue(style, out substate);

    public MotionData? FindCycle(uint key) =>
        (_cycles ??= Cycles.ToDictionary(p => p.Key, p => p.Value)).GetValueOrDefault(key);

    public MotionData? FindLink(uint key, uint to) =>
        (_links ??= Links.ToDictionary(p => p.Key, p => p.Value.ToDictionary(q => q.Key, q => q.Value))).TryGetValue(key, out var inner)
            ? inner.GetValueOrDefault(to) : null;

    public static MotionTable Read(DatBinaryReader r)
    {
        var id = r.ReadUInt32();
        var defaultStyle = r.ReadUInt32();
        var styles = new KeyValuePair<uint, uint>[r.ReadCount(r.ReadUInt32(), 8, "style default")];
        for (var i = 0; i < styles.Length; i++) styles[i] = new(r.ReadUInt32(), r.ReadUInt32());
        Unique(styles.Select(p => p.Key), "StyleDefaults", "style");
        var cycles = ReadMotions(r, "cycle");
        var modifiers = ReadMotions(r, "modifier");
        var links = new KeyValuePair<uint, IReadOnlyList<KeyValuePair<uint, MotionData>>>[r.ReadCount(r.ReadUInt32(), 8, "link")];
        for (var i = 0; i < links.Length; i++)
        {
            var key = r.ReadUInt32();
            links[i] = new(key, ReadMotions(r, $"link 0x{key:X8} target"));
        }
        Unique(links.Select(p => p.Key), "Links", "key");
        return new MotionTable(id, defaultStyle, styles, cycles, modifiers, links);
    }

    private static KeyValuePair<uint, MotionData>[] ReadMotions(DatBinaryReader r, string what)
    {
        var motions = new KeyValuePair<uint, MotionData>[r.ReadCount(r.ReadUInt32(), 4 + MotionData.MinBytes, what)];
        for (var i = 0; i < motions.Length; i++) motions[i] = new(r.ReadUInt32(), MotionData.Read(r));
        Unique(motions.Select(p => p.Key), what, "key");
        return motions;
    }

    /// <summary>Every reader keeps these maps as dictionaries: a key listed twice has no single meaning.</summary>
    private static void Unique(IEnumerable<uint> keys, string map, string what)
    {
        var seen = new HashSet<uint>();
        foreach (var key in keys)
            if (!seen.Add(key)) throw new DatFormatException($"{map} lists {what} 0x{key:X8} twice");
    }

    public void Write(DatBinaryWriter w)
    {
        w.WriteUInt32(Id);
        w.WriteUInt32(DefaultStyle);
        w.WriteUInt32((uint)StyleDefaults.Count);
        foreach (var (style, substate) in StyleDefaults) { w.WriteUInt32(style); w.WriteUInt32(substate); }
        WriteMotions(w, Cycles);
        WriteMotions(w, Modifiers);
        w.WriteUInt32((uint)Links.Count);
        foreach (var (key, targets) in Links) { w.WriteUInt32(key); WriteMotions(w, targets); }
    }

    private static void WriteMotions(DatBinaryWriter w, IReadOnlyList<KeyValuePair<uint, MotionData>> motions)
    {
        w.WriteUInt32((uint)motions.Count);
        foreach (var (key, motion) in motions) { w.WriteUInt32(key); motion.Write(w); }
    }
}
