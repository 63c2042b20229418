using System.Security.Cryptography;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Formats;

/// <summary>
/// What index.json lists about one written file: enough to describe it (and to find it unchanged on
/// disk) without keeping its bytes, so a batch's memory does not grow with the output.
/// </summary>
public sealed record FileEntry(string RelativePath, FixtureKind Kind, uint Id, int ShapeCount, int PolygonCount, long Bytes, string Sha256)
{
    /// <summary>The entry of an export's file (one with a <see cref="OutputFile.Listing"/>).</summary>
    public static FileEntry Of(OutputFile file)
    {
        var listing = file.Listing ?? throw new ArgumentException($"{file.RelativePath} is no export file: index.json lists only those", nameof(file));
        return new(file.RelativePath, listing.Kind, listing.Id, listing.ShapeCount, listing.PolygonCount, file.Content.Length,
            Convert.ToHexStringLower(SHA256.HashData(file.Content.Span)));
    }
}
