using AcShadow.Fixtures.Collision;

namespace AcShadow.Fixtures.Scenes;

/// <summary>An indoor cell of a scene as a query: its id and its retail tree in the cell's frame (EnvCell::find_env_collisions).</summary>
internal sealed record SceneCell(uint CellId, CellOverlapQuery Query);
