using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Formats;

/// <summary>
/// One file of an export, in memory: where it goes (relative, '/' separated), what it is, its bytes. A file
/// handed to a streaming batch's writer may lend its bytes (<see cref="Json.Utf8JsonText.Lend"/>): they are
/// valid only during that call, so a writer that keeps files keeps a copy.
/// </summary>
public sealed record OutputFile(string RelativePath, FixtureKind Kind, uint Id, ReadOnlyMemory<byte> Content, int ShapeCount, int PolygonCount)
{
    /// <summary>
    /// Makes the same content as acdream's fixture file, from the records this file was written from (null: the
    /// format has no acdream shape). Made only when the run asks for acdream's format.
    /// </summary>
    public Func<OutputFile>? Acdream { get; init; }
}
