using System.Text.Json;
using Json.Schema;

namespace AcShadow.Tests.Schemas;

/// <summary>
/// The schemas under schemas/, validated by JsonSchema.Net (JSON Schema 2020-12). Each error is
/// "INSTANCE-LOCATION: KEYWORD: message", so a test can name the keyword a broken file trips.
/// </summary>
public sealed class SchemaValidator
{
    private readonly BuildOptions _build = new() { SchemaRegistry = new SchemaRegistry() };
    private readonly Dictionary<string, JsonSchema> _schemas = [];

    public void Add(JsonElement schema)
    {
        var id = schema.GetProperty("$id").GetString()!;
        _schemas[id] = JsonSchema.Build(schema.Clone(), _build, new Uri(id));
    }

    public IReadOnlyList<string> Validate(JsonElement document, string schemaId)
    {
        var results = _schemas[schemaId].Evaluate(document, new EvaluationOptions { OutputFormat = OutputFormat.List });
        if (results.IsValid) return [];
        return (results.Details ?? [])
            .Prepend(results)
            .Where(d => d.Errors is { Count: > 0 })
            .SelectMany(d => d.Errors!.Select(e => $"{d.InstanceLocation}: {e.Key}: {e.Value}"))
            .Distinct()
            .ToArray();
    }
}
