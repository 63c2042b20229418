using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// One object a landblock places, as scene.json and cell files list it (a cell's are the EnvCell's stabs):
/// what it is, where it stands and the file that describes it.
/// </summary>
/// <param name="Index">Its position in the landblock's placement list.</param>
/// <param name="Id">The Setup (0x02…) or GfxObj (0x01…) id it places.</param>
/// <param name="Kind">Whether the id is a Setup, a bare GfxObj, or neither.</param>
/// <param name="LandblockFrame">Its frame relative to the landblock's corner, as the dat stores it.</param>
/// <param name="WorldFrame">The same frame in world coordinates (metres).</param>
/// <param name="File">Output-relative path of its shadow file (setup) or BSP dump (gfxObj); null when unresolved or drawing-only.</param>
/// <param name="Shapes">A bare GfxObj's one BSP shape (empty for setups, whose shapes are in their shadow file).</param>
public sealed record PlacedObject(int Index, uint Id, SceneObjectKind Kind, Frame LandblockFrame, Frame WorldFrame, string? File, IReadOnlyList<ShadowShape> Shapes);
