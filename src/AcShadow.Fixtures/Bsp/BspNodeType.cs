namespace AcShadow.Fixtures.Bsp;

/// <summary>
/// BSP node tags: four ASCII characters read as a little-endian int, so "LEAF" is 0x4C454146.
/// Capital P / N: the node has a positive / negative child.
/// </summary>
public enum BspNodeType : uint
{
    Leaf = 0x4C454146,   // LEAF
    Portal = 0x504F5254, // PORT (drawing/cell trees only)
    BPnn = 0x42506E6E,
    BPIn = 0x4250496E,
    BpIN = 0x4270494E,
    BpnN = 0x42706E4E,
    BPIN = 0x4250494E,
    BPnN = 0x42506E4E,
}

internal static class BspNodeTypes
{
    public static string Tag(this BspNodeType type) => new(type.Tag(stackalloc char[4]));

    /// <summary>The tag's four characters in <paramref name="chars"/> (a writer's stack space, no string per node).</summary>
    public static ReadOnlySpan<char> Tag(this BspNodeType type, Span<char> chars)
    {
        var v = (uint)type;
        chars[0] = (char)(v >> 24);
        chars[1] = (char)((v >> 16) & 0xFF);
        chars[2] = (char)((v >> 8) & 0xFF);
        chars[3] = (char)(v & 0xFF);
        return chars[..4];
    }

    public static bool HasPos(this BspNodeType t) => t is BspNodeType.BPnn or BspNodeType.BPIn or BspNodeType.BPIN or BspNodeType.BPnN;
    public static bool HasNeg(this BspNodeType t) => t is BspNodeType.BpIN or BspNodeType.BpnN or BspNodeType.BPIN or BspNodeType.BPnN;
    public static bool IsInternal(this BspNodeType t) => t.HasPos() || t.HasNeg();

    /// <summary>The tag for an internal node with the given children.</summary>
    public static BspNodeType ForChildren(bool pos, bool neg) => (pos, neg) switch
    {
        (true, true) => BspNodeType.BPIN,
        (true, false) => BspNodeType.BPIn,
        (false, true) => BspNodeType.BpIN,
        _ => throw new ArgumentException("an internal BSP node needs at least one child"),
    };
}
