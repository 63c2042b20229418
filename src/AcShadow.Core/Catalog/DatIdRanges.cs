namespace AcShadow.Core.Catalog;

/// <summary>
/// What an id names in the retail dats, from its range alone: portal objects by their top byte, cell
/// objects by their low word. Used to say what a wrong id is ("a GfxObj id") rather than only that it is
/// outside the Setup range.
/// </summary>
public static class DatIdRanges
{
    private static readonly Dictionary<uint, string> PortalTypes = new()
    {
        [0x01] = "GfxObj",
        [0x03] = "Animation",
        [0x04] = "Palette",
        [0x05] = "SurfaceTexture",
        [0x06] = "Texture",
        [0x08] = "Surface",
        [0x09] = "MotionTable",
        [0x0A] = "Wave",
        [0x0D] = "Environment",
        [0x0F] = "PaletteSet",
        [0x10] = "Clothing",
        [0x11] = "GfxObjDegradeInfo",
        [0x12] = "Scene",
        [0x13] = "Region",
        [0x20] = "SoundTable",
        [0x32] = "ParticleEmitter",
        [0x33] = "PhysicsScript",
        [0x34] = "PhysicsScriptTable",
    };

    /// <summary>
    /// "a GfxObj id", "a LandBlockInfo id (a cell dat object)", … or null when the range names nothing
    /// known. Setups are not named: the caller says what a Setup id must be.
    /// </summary>
    public static string? Describe(uint id)
    {
        if (PortalTypes.TryGetValue(id >> 24, out var name)) return $"a {name} id";
        if (id >> 16 == 0) return null;
        return (id & 0xFFFF) switch
        {
            0xFFFF => "a landblock id (a cell dat object)",
            0xFFFE => "a LandBlockInfo id (a cell dat object)",
            >= 0x0100 => "an EnvCell id (a cell dat object)",
            _ => null,
        };
    }
}
