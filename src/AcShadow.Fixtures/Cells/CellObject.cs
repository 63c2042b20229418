using System.Numerics;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures.Cells;

/// <summary>
/// An object placed inside a cell (the EnvCell's stabs): its landblock-relative frame, its world origin,
/// and the file that describes it (a Setup's shadow file, or a bare GfxObj's BSP dump with its one shape).
/// </summary>
public sealed record CellObject(int Index, uint Id, SceneObjectKind Kind, Vector3 LandblockPosition, Quaternion Rotation, Vector3 WorldPosition,
    string? File, IReadOnlyList<ShadowShape> Shapes);
