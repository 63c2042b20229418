using System.Numerics;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>One object scene.json places: what it is, where it stands in the world, and the file that describes it.</summary>
/// <param name="Index">Its position in the landblock's placement list.</param>
/// <param name="Id">The Setup (0x02…) or GfxObj (0x01…) id it places.</param>
/// <param name="Kind">Whether the id is a Setup, a bare GfxObj, or neither.</param>
/// <param name="WorldPosition">Its origin in world coordinates (metres).</param>
/// <param name="WorldRotation">Its orientation in the world.</param>
/// <param name="File">Output-relative path of its shadow file (setup) or BSP dump (gfxObj); null when unresolved or drawing-only.</param>
/// <param name="Shapes">A bare GfxObj's one BSP shape (empty for setups, whose shapes are in their shadow file).</param>
public sealed record ScenePlacement(int Index, uint Id, SceneObjectKind Kind, Vector3 WorldPosition, Quaternion WorldRotation, string? File, IReadOnlyList<ShadowShape> Shapes);
