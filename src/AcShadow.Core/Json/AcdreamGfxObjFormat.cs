using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Json;

/// <summary>
/// acdream's GfxObj fixture shape (its collision tests load these): the file carries no format field, its
/// field names are acdream's. docs/formats.md gives the mapping from the canonical BSP file.
/// </summary>
public static class AcdreamGfxObjFormat
{
    /// <summary>Beside the canonical dumps: gfxobjs/0x%08X.gfxobj.json.</summary>
    public static string PathFor(uint gfxObjId) => $"gfxobjs/{JsonIds.Format(gfxObjId)}.gfxobj.json";
}
