using System.Text.Json;
using AcShadow.Fixtures.Batch;
using AcShadow.Fixtures.Json;
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
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Index, "index.json");
        var inputs = BspFileReader.Prop(root, "inputs");
        var policyText = BspFileReader.Str(inputs, "policy");
        if (!ShapePolicies.TryParse(policyText, out var policy)) throw new FormatException($"inputs.policy \"{policyText}\" is not retail or union");
        var files = BspFileReader.Arr(root, "files").Select(f => new IndexedFile(
            BspFileReader.Str(f, "path"), Kind(BspFileReader.Str(f, "kind")), BspFileReader.Str(f, "id"), BspFileReader.Str(f, "sha256"))).ToArray();
        return new FixtureIndex(policy, BspFileReader.Float(inputs, "entityScale"), files);
    }

    private static FixtureKind Kind(string name) =>
        FixtureKinds.TryParse(name, out var kind) ? kind : throw new FormatException($"files: kind \"{name}\" is not a kind of file acshadow writes");
}
