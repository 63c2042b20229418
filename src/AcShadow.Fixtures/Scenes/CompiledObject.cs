using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Scenes;

/// <summary>One placed object of a compiled scene: what it is, the model chosen for it and how many shapes that model tests.</summary>
internal sealed record CompiledObject(int Index, uint Id, SceneObjectKind Kind, string? Model, int Shapes, Frame LandblockFrame)
{
    /// <summary>The indoor cell the object stands in, when a cell placed it.</summary>
    public uint? CellId { get; init; }
}
