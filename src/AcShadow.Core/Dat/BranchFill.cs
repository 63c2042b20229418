namespace AcShadow.Core.Dat;

/// <summary>
/// What a directory B-tree node holds in its unused branch slots. Retail dats write 0 (and mark a leaf by a
/// zero first branch); DatReaderWriter, which many community tools use to write or patch dats, writes
/// 0xCDCDCDCD and reads that value as "no branch". Both open; the style says which tool wrote the directory.
/// </summary>
public enum BranchFill
{
    /// <summary>No unused slot (a full internal node), or no node at all.</summary>
    None,
    /// <summary>Every unused slot is 0: retail's style.</summary>
    Zero,
    /// <summary>Every unused slot is 0xCDCDCDCD: DatReaderWriter's style.</summary>
    Cdcd,
    /// <summary>Nodes of both styles (a retail dat patched by a DatReaderWriter-based tool).</summary>
    Mixed,
    /// <summary>Some unused slot holds another value (ignored: only the first entry count + 1 slots are branches).</summary>
    Other,
}

public static class BranchFills
{
    /// <summary>DatReaderWriter's "no branch" value.</summary>
    public const int Cdcd = unchecked((int)0xCDCDCDCD);

    /// <summary>Whether a branch slot means "no branch" in either style.</summary>
    public static bool IsNoBranch(int slot) => slot is 0 or Cdcd;

    /// <summary>The fill of a whole directory from its nodes' fills.</summary>
    public static BranchFill Combine(this BranchFill a, BranchFill b) => (a, b) switch
    {
        (BranchFill.None, _) => b,
        (_, BranchFill.None) => a,
        (BranchFill.Other, _) or (_, BranchFill.Other) => BranchFill.Other,
        _ when a == b => a,
        _ => BranchFill.Mixed,
    };

    /// <summary>The word a report uses: "zero (retail)", "0xCDCDCDCD (DatReaderWriter)", ...</summary>
    public static string Describe(this BranchFill fill) => fill switch
    {
        BranchFill.None => "none (no unused branch slot)",
        BranchFill.Zero => "zero (retail)",
        BranchFill.Cdcd => "0xCDCDCDCD (DatReaderWriter)",
        BranchFill.Mixed => "mixed: zero and 0xCDCDCDCD (a retail dat patched by a DatReaderWriter-based tool)",
        _ => "other values",
    };
}
