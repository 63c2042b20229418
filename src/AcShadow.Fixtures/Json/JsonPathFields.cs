using System.Text.Json;

namespace AcShadow.Fixtures.Json;

/// <summary>
/// Fields read with their JSONPath in the error ("$.inputs.policy is missing"), for files such as
/// index.json where a person fixes the field by hand.
/// </summary>
internal static class JsonPathFields
{
    public static JsonElement Member(JsonElement e, string name, string at)
    {
        if (e.ValueKind != JsonValueKind.Object) throw new FormatException($"{at} is not an object");
        return e.TryGetProperty(name, out var v) ? v : throw new FormatException($"{at}.{name} is missing");
    }

    public static string Str(JsonElement e, string name, string at)
    {
        var v = Member(e, name, at);
        return v.ValueKind == JsonValueKind.String ? v.GetString()! : throw new FormatException($"{at}.{name} is not a string");
    }

    public static long Num(JsonElement e, string name, string at)
    {
        var v = Member(e, name, at);
        return v.ValueKind == JsonValueKind.Number && v.TryGetInt64(out var n) ? n
            : throw new FormatException($"{at}.{name} is not an integer");
    }

    public static bool Bool(JsonElement e, string name, string at)
    {
        var v = Member(e, name, at);
        return v.ValueKind switch
        {
            JsonValueKind.True => true,
            JsonValueKind.False => false,
            _ => throw new FormatException($"{at}.{name} is not true or false"),
        };
    }
}
