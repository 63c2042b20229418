using System.Text.Json;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Fixtures.Json.JsonPathFields;

namespace AcShadow.Fixtures.Batch;

/// <summary>
/// The one parser of index.json's body (its format checked by the caller): the policy and entity scale the
/// files were made with, whatever else of <c>inputs</c> the caller reads, and the files. Errors name the
/// field's JSONPath.
/// </summary>
internal static class IndexFileReader
{
    /// <param name="root">The document's root, its <c>format</c> already checked.</param>
    /// <param name="readInputs">Reads the rest of <c>$.inputs</c> (verify's regeneration inputs), after the policy and scale.</param>
    public static IndexFileBody<TInputs> Read<TInputs>(JsonElement root, Func<JsonElement, ShapePolicy, float, TInputs> readInputs)
    {
        var inputs = Member(root, "inputs", "$");
        var policyText = Str(inputs, "policy", "$.inputs");
        if (!ShapePolicies.TryParse(policyText, out var policy)) throw new FormatException($"$.inputs.policy \"{policyText}\" is not retail or union");
        var scale = Member(inputs, "entityScale", "$.inputs");
        if (scale.ValueKind != JsonValueKind.Number) throw new FormatException("$.inputs.entityScale is not a number");
        var entityScale = scale.GetSingle();
        var more = readInputs(inputs, policy, entityScale);
        var files = Member(root, "files", "$");
        if (files.ValueKind != JsonValueKind.Array) throw new FormatException("$.files is not an array");
        var list = files.EnumerateArray().Select((f, i) =>
        {
            var at = $"$.files[{i}]";
            var kind = Str(f, "kind", at);
            return new IndexedFile(Str(f, "path", at), FixtureKinds.TryParse(kind, out var k) ? k : throw new FormatException($"{at}.kind \"{kind}\" is not a kind of file acshadow writes"),
                Str(f, "id", at), Str(f, "sha256", at));
        }).ToArray();
        return new IndexFileBody<TInputs>(policy, entityScale, more, list);
    }
}
