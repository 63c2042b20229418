using System.Text.Json;
using System.Text.RegularExpressions;

namespace AcShadow.Tests.Schemas;

/// <summary>
/// A JSON Schema (2020-12) validator for exactly the keywords schemas/ uses — no validator package
/// restores here (JsonSchema.Net lacks its JsonPointer.Net dependency on this feed; NJsonSchema has no
/// compatible version). A schema using any other keyword is refused, so nothing is silently ignored.
/// $ref takes "#/$defs/name" or "urn:…#/$defs/name" naming another loaded schema.
/// </summary>
public sealed class SchemaValidator
{
    public static readonly IReadOnlySet<string> Keywords = new HashSet<string>
    {
        "$schema", "$id", "$defs", "$ref", "title", "description",
        "type", "const", "enum", "properties", "required", "additionalProperties", "items", "minItems", "maxItems",
        "minimum", "maximum", "exclusiveMinimum", "pattern", "oneOf", "if", "then", "else",
    };

    private readonly Dictionary<string, JsonElement> _schemas = [];

    public void Add(JsonElement schema)
    {
        var id = schema.GetProperty("$id").GetString()!;
        CheckKeywords(schema, id);
        _schemas[id] = schema.Clone();
    }

    public IReadOnlyList<string> Validate(JsonElement document, string schemaId)
    {
        var errors = new List<string>();
        Check(document, _schemas[schemaId], schemaId, "$", errors);
        return errors;
    }

    private void Check(JsonElement value, JsonElement schema, string baseId, string at, List<string> errors)
    {
        if (schema.TryGetProperty("$ref", out var reference))
        {
            var (target, targetBase) = Resolve(reference.GetString()!, baseId);
            Check(value, target, targetBase, at, errors);
        }
        if (schema.TryGetProperty("type", out var type) && !TypeMatches(value, type))
            errors.Add($"{at}: {value.ValueKind} is not of type {type.GetRawText()}");
        if (schema.TryGetProperty("const", out var constant) && !JsonElement.DeepEquals(value, constant))
            errors.Add($"{at}: {value.GetRawText()} is not {constant.GetRawText()}");
        if (schema.TryGetProperty("enum", out var options) && !options.EnumerateArray().Any(o => JsonElement.DeepEquals(value, o)))
            errors.Add($"{at}: {value.GetRawText()} is not one of {options.GetRawText()}");
        if (value.ValueKind == JsonValueKind.Number)
        {
            var n = value.GetDouble();
            if (schema.TryGetProperty("minimum", out var min) && n < min.GetDouble()) errors.Add($"{at}: {n} < minimum {min.GetDouble()}");
            if (schema.TryGetProperty("maximum", out var max) && n > max.GetDouble()) errors.Add($"{at}: {n} > maximum {max.GetDouble()}");
            if (schema.TryGetProperty("exclusiveMinimum", out var emin) && n <= emin.GetDouble()) errors.Add($"{at}: {n} <= exclusiveMinimum {emin.GetDouble()}");
        }
        if (value.ValueKind == JsonValueKind.String && schema.TryGetProperty("pattern", out var pattern)
            && !Regex.IsMatch(value.GetString()!, pattern.GetString()!, RegexOptions.CultureInvariant))
            errors.Add($"{at}: \"{value.GetString()}\" does not match {pattern.GetString()}");
        if (value.ValueKind == JsonValueKind.Object)
        {
            if (schema.TryGetProperty("required", out var required))
                foreach (var name in required.EnumerateArray().Select(r => r.GetString()!).Where(n => !value.TryGetProperty(n, out _)))
                    errors.Add($"{at}: missing \"{name}\"");
            var declared = schema.TryGetProperty("properties", out var properties) ? properties : default;
            foreach (var member in value.EnumerateObject())
            {
                if (declared.ValueKind == JsonValueKind.Object && declared.TryGetProperty(member.Name, out var sub))
                    Check(member.Value, sub, baseId, $"{at}.{member.Name}", errors);
                else if (schema.TryGetProperty("additionalProperties", out var additional) && additional.ValueKind == JsonValueKind.False)
                    errors.Add($"{at}: \"{member.Name}\" is not allowed");
            }
        }
        if (value.ValueKind == JsonValueKind.Array)
        {
            var count = value.GetArrayLength();
            if (schema.TryGetProperty("minItems", out var minItems) && count < minItems.GetInt32()) errors.Add($"{at}: {count} item(s) < minItems {minItems.GetInt32()}");
            if (schema.TryGetProperty("maxItems", out var maxItems) && count > maxItems.GetInt32()) errors.Add($"{at}: {count} item(s) > maxItems {maxItems.GetInt32()}");
            if (schema.TryGetProperty("items", out var items))
            {
                var i = 0;
                foreach (var item in value.EnumerateArray()) Check(item, items, baseId, $"{at}[{i++}]", errors);
            }
        }
        if (schema.TryGetProperty("oneOf", out var oneOf))
        {
            var matching = oneOf.EnumerateArray().Count(s => { var e = new List<string>(); Check(value, s, baseId, at, e); return e.Count == 0; });
            if (matching != 1) errors.Add($"{at}: matches {matching} of oneOf's schemas, not exactly 1");
        }
        if (schema.TryGetProperty("if", out var condition))
        {
            var e = new List<string>();
            Check(value, condition, baseId, at, e);
            if (e.Count == 0 && schema.TryGetProperty("then", out var then)) Check(value, then, baseId, at, errors);
            if (e.Count > 0 && schema.TryGetProperty("else", out var otherwise)) Check(value, otherwise, baseId, at, errors);
        }
    }

    private (JsonElement Schema, string BaseId) Resolve(string reference, string baseId)
    {
        var hash = reference.IndexOf('#');
        var id = hash <= 0 ? (hash == 0 ? baseId : reference) : reference[..hash];
        if (!_schemas.TryGetValue(id, out var schema)) throw new InvalidOperationException($"$ref {reference}: no schema {id} is loaded");
        var node = schema;
        if (hash >= 0)
            foreach (var part in reference[(hash + 1)..].Split('/', StringSplitOptions.RemoveEmptyEntries))
                node = node.GetProperty(part);
        return (node, id);
    }

    private static bool TypeMatches(JsonElement value, JsonElement type) =>
        type.ValueKind == JsonValueKind.Array ? type.EnumerateArray().Any(t => Is(value, t.GetString()!)) : Is(value, type.GetString()!);

    private static bool Is(JsonElement value, string type) => type switch
    {
        "object" => value.ValueKind == JsonValueKind.Object,
        "array" => value.ValueKind == JsonValueKind.Array,
        "string" => value.ValueKind == JsonValueKind.String,
        "boolean" => value.ValueKind is JsonValueKind.True or JsonValueKind.False,
        "null" => value.ValueKind == JsonValueKind.Null,
        "number" => value.ValueKind == JsonValueKind.Number,
        "integer" => value.ValueKind == JsonValueKind.Number && double.IsInteger(value.GetDouble()),
        _ => throw new InvalidOperationException($"unknown type \"{type}\""),
    };

    private static void CheckKeywords(JsonElement schema, string at)
    {
        if (schema.ValueKind != JsonValueKind.Object) return;
        foreach (var member in schema.EnumerateObject())
        {
            if (!Keywords.Contains(member.Name))
                throw new InvalidOperationException($"{at}: keyword \"{member.Name}\" is not one this validator implements");
            switch (member.Name)
            {
                case "properties" or "$defs":
                    foreach (var p in member.Value.EnumerateObject()) CheckKeywords(p.Value, $"{at}/{member.Name}/{p.Name}");
                    break;
                case "items" or "if" or "then" or "else":
                    CheckKeywords(member.Value, $"{at}/{member.Name}");
                    break;
                case "oneOf":
                    foreach (var s in member.Value.EnumerateArray()) CheckKeywords(s, $"{at}/oneOf");
                    break;
                case "additionalProperties" when member.Value.ValueKind != JsonValueKind.False:
                    throw new InvalidOperationException($"{at}: additionalProperties other than false is not implemented");
            }
        }
    }
}
