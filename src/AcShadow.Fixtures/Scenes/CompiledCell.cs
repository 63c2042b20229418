using AcShadow.Fixtures.Geometry;

namespace AcShadow.Fixtures.Scenes;

/// <summary>One indoor cell of a compiled scene: always its retail tree, in the cell's landblock-relative frame.</summary>
internal sealed record CompiledCell(uint CellId, string Model, Frame LandblockFrame);
