using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Formats;

/// <summary>What index.json lists of an export's <see cref="OutputFile"/> besides its path and bytes: what it is, of which object, and its counts.</summary>
public sealed record OutputFileListing(FixtureKind Kind, uint Id, int ShapeCount, int PolygonCount);
