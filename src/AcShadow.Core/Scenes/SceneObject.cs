using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Scenes;

/// <summary>Which LandBlockInfo list placed an object.</summary>
public enum ScenePlacedBy
{
    Object,
    Building,
    /// <summary>An EnvCell's static objects (its stabs).</summary>
    Cell,
}

/// <summary>What a placed id is: a Setup (0x02…), a bare GfxObj (0x01…), or something acshadow does not describe.</summary>
public enum SceneObjectKind
{
    Setup,
    GfxObj,
    Other,
}

/// <summary>
/// One object a landblock places: its position in the LandBlockInfo (<see cref="PlacedBy"/>,
/// <see cref="PlacedIndex"/>), its id and kind, and its landblock-relative frame.
/// </summary>
public sealed record SceneObject(int Index, ScenePlacedBy PlacedBy, int PlacedIndex, uint Id, SceneObjectKind Kind, Frame Frame);
