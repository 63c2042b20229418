namespace AcShadow.Core.Formats;

/// <summary>Which file shapes a run writes (`--format canonical|acdream|both`).</summary>
[Flags]
public enum OutputFormats
{
    /// <summary>acshadow's own files: shadow files, BSP dumps, scene.json.</summary>
    Canonical = 1,

    /// <summary>acdream's GfxObj fixtures (0x%08X.gfxobj.json), one per BSP dump.</summary>
    Acdream = 2,

    Both = Canonical | Acdream,
}

public static class OutputFormatNames
{
    public static string Name(this OutputFormats formats) => formats switch
    {
        OutputFormats.Canonical => "canonical",
        OutputFormats.Acdream => "acdream",
        OutputFormats.Both => "both",
        _ => throw new ArgumentOutOfRangeException(nameof(formats)),
    };

    public static bool TryParse(string? text, out OutputFormats formats)
    {
        switch (text?.Trim().ToLowerInvariant())
        {
            case "canonical": formats = OutputFormats.Canonical; return true;
            case "acdream": formats = OutputFormats.Acdream; return true;
            case "both": formats = OutputFormats.Both; return true;
            default: formats = default; return false;
        }
    }
}
