using System.Security.Cryptography;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Formats;

/// <summary>
/// What index.json lists about one written file: enough to describe it (and to find it unchanged on
/// disk) without keeping its bytes, so a batch's memory does not grow with the output.
/// </summary>
public sealed record FileEntry(string RelativePath, FixtureKind Kind, uint Id, int ShapeCount, int PolygonCount, long Bytes, string Sha256)
{
    public static FileEntry Of(OutputFile file) =>
        new(file.RelativePath, file.Kind, file.Id, file.ShapeCount, file.PolygonCount, file.Content.Length,
            Convert.ToHexStringLower(SHA256.HashData(file.Content.Span)));
}
