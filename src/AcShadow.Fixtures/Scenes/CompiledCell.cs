using System.Numerics;

namespace AcShadow.Fixtures.Scenes;

/// <summary>One indoor cell of a compiled scene: always its retail tree, in the cell's landblock-relative frame.</summary>
internal sealed record CompiledCell(uint CellId, string Model, Vector3 LandblockPosition, Quaternion LandblockRotation);
