namespace AcShadow.Fixtures;

/// <summary>One indoor cell scene.json lists: its id and its cell file (null when it could not be described).</summary>
internal sealed record SceneCellFile(uint Id, string? File);
