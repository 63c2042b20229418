using System.Collections;
using System.Text.Json.Serialization.Metadata;
using System.Text.Json.Serialization;
using System.Text.Json;
using System.Text;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Forging.Spec;

/// <summary>
/// Reads and writes <see cref="ForgeSpec"/> JSON. Strict on read (unknown properties and duplicate
/// keys are errors, so a typo cannot silently drop a field); compact on write (a vector, quaternion
/// or polygon stays on one line) so a 300-polygon GfxObj remains readable.
/// </summary>
public static class SpecJson
{
    private static readonly JsonSerializerOptions Options = CreateOptions();
    private static readonly JsonTypeInfo<ForgeSpec> SpecType = (JsonTypeInfo<ForgeSpec>)Options.GetTypeInfo(typeof(ForgeSpec));
    private static readonly JsonTypeInfo<string> NameType = (JsonTypeInfo<string>)Options.GetTypeInfo(typeof(string));

    private static JsonSerializerOptions CreateOptions()
    {
        var options = new JsonSerializerOptions
        {
            PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
            ReadCommentHandling = JsonCommentHandling.Skip,
            AllowTrailingCommas = true,
            AllowDuplicateProperties = false,
            UnmappedMemberHandling = JsonUnmappedMemberHandling.Disallow,
            NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals,
            DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingDefault,
            Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
            // Source-generated metadata: the CLI that builds the sample from it is published ahead-of-time.
            TypeInfoResolver = SpecJsonContext.Default.WithAddedModifier(OmitEmptyCollections),
        };
        options.Converters.Add(new VectorConverter());
        options.Converters.Add(new QuaternionConverter());
        options.Converters.Add(new PolygonConverter());
        return options;
    }

    /// <summary>Parses a spec; malformed JSON becomes a <see cref="SpecException"/> naming line and position.</summary>
    public static ForgeSpec Parse(string json, string sourceName = "spec")
    {
        try
        {
            return JsonSerializer.Deserialize(json, SpecType)
                ?? throw new SpecException($"{sourceName}: the spec is JSON null; expected an object {{ \"gfxObjs\": [...], \"setups\": [...] }}");
        }
        catch (JsonException e)
        {
            // JsonException line/position are 0-based; editors count from 1.
            var where = e.LineNumber is { } line ? $" at line {line + 1}, position {(e.BytePositionInLine ?? 0) + 1}" : "";
            var path = string.IsNullOrEmpty(e.Path) ? "" : $" ({e.Path})";
            throw new SpecException($"{sourceName}: malformed JSON{where}{path}: {FirstSentence(e.Message)}");
        }
    }

    public static ForgeSpec Load(string path)
    {
        string text;
        try { text = File.ReadAllText(path); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new SpecException($"{path}: cannot read the spec: {e.Message}");
        }
        return Parse(text, path);
    }

    /// <summary>Indented JSON in which vectors, id lists, polygons, frames and other short leaves stay on one line.</summary>
    public static string Serialize(ForgeSpec spec)
    {
        using var document = JsonDocument.Parse(JsonSerializer.Serialize(spec, SpecType));
        var sb = new StringBuilder();
        Format(document.RootElement, sb, "");
        return sb.Append('\n').ToString();
    }

    private const int InlineWidth = 120;

    private static void Format(JsonElement e, StringBuilder sb, string indent)
    {
        if (Inline(e)) { Compact(e, sb); return; }
        var inner = indent + "  ";
        var first = true;
        if (e.ValueKind == JsonValueKind.Object)
        {
            sb.Append("{\n");
            foreach (var p in e.EnumerateObject())
            {
                if (!first) sb.Append(",\n");
                first = false;
                sb.Append(inner).Append(JsonSerializer.Serialize(p.Name, NameType)).Append(": ");
                Format(p.Value, sb, inner);
            }
            sb.Append('\n').Append(indent).Append('}');
            return;
        }
        sb.Append("[\n");
        foreach (var item in e.EnumerateArray())
        {
            if (!first) sb.Append(",\n");
            first = false;
            sb.Append(inner);
            Format(item, sb, inner);
        }
        sb.Append('\n').Append(indent).Append(']');
    }

    /// <summary>Primitives and arrays of primitives always; small objects of such values when they fit a line.</summary>
    private static bool Inline(JsonElement e) => e.ValueKind switch
    {
        JsonValueKind.Array => e.EnumerateArray().All(Primitive),
        JsonValueKind.Object => e.EnumerateObject().All(p => Primitive(p.Value) || p.Value.ValueKind == JsonValueKind.Array && Inline(p.Value)
                || p.Value.ValueKind == JsonValueKind.Object && p.Value.EnumerateObject().All(q => Primitive(q.Value)))
            && CompactLength(e) <= InlineWidth,
        _ => true,
    };

    private static bool Primitive(JsonElement e) => e.ValueKind is not (JsonValueKind.Array or JsonValueKind.Object);

    private static int CompactLength(JsonElement e)
    {
        var sb = new StringBuilder();
        Compact(e, sb);
        return sb.Length;
    }

    private static void Compact(JsonElement e, StringBuilder sb)
    {
        var first = true;
        switch (e.ValueKind)
        {
            case JsonValueKind.Object:
                sb.Append('{');
                foreach (var p in e.EnumerateObject())
                {
                    if (!first) sb.Append(", ");
                    first = false;
                    sb.Append(JsonSerializer.Serialize(p.Name, NameType)).Append(": ");
                    Compact(p.Value, sb);
                }
                sb.Append('}');
                break;
            case JsonValueKind.Array:
                sb.Append('[');
                foreach (var item in e.EnumerateArray())
                {
                    if (!first) sb.Append(", ");
                    first = false;
                    Compact(item, sb);
                }
                sb.Append(']');
                break;
            default:
                sb.Append(e.GetRawText());
                break;
        }
    }

    private static string FirstSentence(string message)
    {
        var line = message.Split('\n')[0].Trim();
        // System.Text.Json appends its own "Path: ... | LineNumber: ..." which the caller already reports.
        var cut = line.IndexOf(" Path:", StringComparison.Ordinal);
        return cut > 0 ? line[..cut] : line;
    }

    private static void OmitEmptyCollections(JsonTypeInfo type)
    {
        foreach (var property in type.Properties)
        {
            if (property.PropertyType == typeof(string) || !typeof(IEnumerable).IsAssignableFrom(property.PropertyType)) continue;
            if (property.PropertyType == typeof(double[])) continue;
            property.ShouldSerialize = (_, value) => value is not null and not ICollection { Count: 0 };
        }
    }

    private static double ReadNumber(ref Utf8JsonReader reader)
    {
        if (reader.TokenType == JsonTokenType.Number)
            return reader.TryGetDouble(out var d) ? d : double.PositiveInfinity; // too large for a double: let the validator name it
        if (reader.TokenType == JsonTokenType.String)
        {
            var s = reader.GetString();
            if (s is "NaN") return double.NaN;
            if (s is "Infinity") return double.PositiveInfinity;
            if (s is "-Infinity") return double.NegativeInfinity;
        }
        throw new JsonException($"expected a number, found {reader.TokenType}");
    }

    /// <summary>[x, y, z] on one line.</summary>
    private sealed class VectorConverter : JsonConverter<double[]>
    {
        public override double[] Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
        {
            if (reader.TokenType != JsonTokenType.StartArray) throw new JsonException("expected a vector [x, y, z]");
            var values = new List<double>(3);
            while (reader.Read() && reader.TokenType != JsonTokenType.EndArray) values.Add(ReadNumber(ref reader));
            return [.. values];
        }

        public override void Write(Utf8JsonWriter writer, double[] value, JsonSerializerOptions options)
        {
            writer.WriteStartArray();
            foreach (var v in value) writer.WriteNumberValue(v);
            writer.WriteEndArray();
        }
    }

    /// <summary>{"w": .., "x": .., "y": .., "z": ..} on one line; a missing component is an error.</summary>
    private sealed class QuaternionConverter : JsonConverter<QuaternionSpec>
    {
        public override QuaternionSpec Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
        {
            if (reader.TokenType != JsonTokenType.StartObject) throw new JsonException("expected an orientation {\"w\": 1, \"x\": 0, \"y\": 0, \"z\": 0}");
            double? w = null, x = null, y = null, z = null;
            while (reader.Read() && reader.TokenType != JsonTokenType.EndObject)
            {
                var name = reader.GetString();
                reader.Read();
                var v = ReadNumber(ref reader);
                switch (name)
                {
                    case "w": w = v; break;
                    case "x": x = v; break;
                    case "y": y = v; break;
                    case "z": z = v; break;
                    default: throw new JsonException($"orientation has no component \"{name}\" (use w, x, y, z)");
                }
            }
            if (w is null || x is null || y is null || z is null) throw new JsonException("an orientation needs all of w, x, y, z");
            return new QuaternionSpec(w.Value, x.Value, y.Value, z.Value);
        }

        public override void Write(Utf8JsonWriter writer, QuaternionSpec q, JsonSerializerOptions options)
        {
            writer.WriteStartObject();
            writer.WriteNumber("w", q.W);
            writer.WriteNumber("x", q.X);
            writer.WriteNumber("y", q.Y);
            writer.WriteNumber("z", q.Z);
            writer.WriteEndObject();
        }
    }

    /// <summary>{"vertices": [..], "sidesType": .., "stippling": ..} on one line.</summary>
    private sealed class PolygonConverter : JsonConverter<PolygonSpec>
    {
        public override PolygonSpec Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
        {
            if (reader.TokenType != JsonTokenType.StartObject) throw new JsonException("expected a polygon {\"vertices\": [0, 1, 2]}");
            var vertices = new List<int>();
            string? sides = null, stippling = null;
            while (reader.Read() && reader.TokenType != JsonTokenType.EndObject)
            {
                var name = reader.GetString();
                reader.Read();
                switch (name)
                {
                    case "vertices":
                        if (reader.TokenType != JsonTokenType.StartArray) throw new JsonException("polygon vertices must be an array of vertex ids");
                        while (reader.Read() && reader.TokenType != JsonTokenType.EndArray)
                        {
                            if (reader.TokenType != JsonTokenType.Number || !reader.TryGetInt32(out var id))
                                throw new JsonException("a polygon vertex id must be a whole number");
                            vertices.Add(id);
                        }
                        break;
                    case "sidesType": sides = reader.GetString(); break;
                    case "stippling": stippling = reader.GetString(); break;
                    default: throw new JsonException($"polygon has no property \"{name}\" (use vertices, sidesType, stippling)");
                }
            }
            return new PolygonSpec { Vertices = vertices, SidesType = sides, Stippling = stippling };
        }

        public override void Write(Utf8JsonWriter writer, PolygonSpec p, JsonSerializerOptions options)
        {
            writer.WriteStartObject();
            writer.WriteStartArray("vertices");
            foreach (var v in p.Vertices) writer.WriteNumberValue(v);
            writer.WriteEndArray();
            if (p.SidesType is not null) writer.WriteString("sidesType", p.SidesType);
            if (p.Stippling is not null) writer.WriteString("stippling", p.Stippling);
            writer.WriteEndObject();
        }
    }
}
