using AcShadow.Core.Dat.Objects;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Core.Scenes;

/// <summary>Which LandBlockInfo list placed an object.</summary>
public enum ScenePlacedBy
{
    Object,
    Building,
    /// <summary>An EnvCell's static objects (its stabs).</summary>
    Cell,
}

/// <summary>
/// One object a landblock places: its position in the LandBlockInfo (<see cref="PlacedBy"/>,
/// <see cref="PlacedIndex"/>), its id and kind, and its landblock-relative frame.
/// </summary>
public sealed record SceneObject(int Index, ScenePlacedBy PlacedBy, int PlacedIndex, uint Id, SceneObjectKind Kind, Frame Frame);
