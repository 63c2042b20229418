using System.Text.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>
/// index.json as a consumer needs it: the policy and entity scale the files were made with, and every file
/// with its kind, id and SHA-256. (The dat identity and selection it also records are for
/// <c>acshadow verify</c>.)
/// </summary>
public sealed record FixtureIndex(ShapePolicy Policy, float EntityScale, IReadOnlyList<IndexedFile> Files)
{
    public IEnumerable<IndexedFile> OfKind(FixtureKind kind) => Files.Where(f => f.Kind == kind);

    public static FixtureIndex Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        FormatCheck.Require(doc.RootElement, FileFormats.Index, "index.json");
        var body = IndexFileReader.Read(doc.RootElement, static (_, _, _) => 0);
        return new FixtureIndex(body.Policy, body.EntityScale, body.Files);
    }
}
