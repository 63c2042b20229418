using System.Globalization;
using System.Numerics;

namespace AcShadow.Core.Json;

/// <summary>
/// A minimal ordered JSON tree: keys keep the order code adds them in (the format's fixed key order),
/// and numbers are turned into their canonical text when the node is made.
/// </summary>
public abstract class JsonNode;

public sealed class JsonObj : JsonNode
{
    public List<KeyValuePair<string, JsonNode>> Members { get; } = [];

    public JsonObj Add(string name, JsonNode value) { Members.Add(new(name, value)); return this; }
    public JsonObj Add(string name, string? value) => Add(name, value is null ? JsonNull.Value : new JsonStr(value));
    public JsonObj Add(string name, float value) => Add(name, JsonNum.Of(value));
    public JsonObj Add(string name, int value) => Add(name, JsonNum.Of(value));
    public JsonObj Add(string name, long value) => Add(name, JsonNum.Of(value));
    public JsonObj Add(string name, bool value) => Add(name, value ? JsonBool.True : JsonBool.False);
    public JsonObj Add(string name, Vector3 value) => Add(name, JsonArr.Of(value));
}

public sealed class JsonArr : JsonNode
{
    public List<JsonNode> Items { get; } = [];

    public JsonArr Add(JsonNode item) { Items.Add(item); return this; }

    public static JsonArr Of(Vector3 v) => new JsonArr().Add(JsonNum.Of(v.X)).Add(JsonNum.Of(v.Y)).Add(JsonNum.Of(v.Z));

    public static JsonArr Of(IEnumerable<int> values)
    {
        var arr = new JsonArr();
        foreach (var v in values) arr.Add(JsonNum.Of(v));
        return arr;
    }

    public static JsonArr Of(IEnumerable<string> values)
    {
        var arr = new JsonArr();
        foreach (var v in values) arr.Add(new JsonStr(v));
        return arr;
    }

    public static JsonArr Of<T>(IEnumerable<T> values, Func<T, JsonNode> map)
    {
        var arr = new JsonArr();
        foreach (var v in values) arr.Add(map(v));
        return arr;
    }
}

public sealed class JsonStr(string value) : JsonNode
{
    public string Value { get; } = value;
}

public sealed class JsonBool : JsonNode
{
    public static readonly JsonBool True = new(true);
    public static readonly JsonBool False = new(false);
    public bool Value { get; }
    private JsonBool(bool value) => Value = value;
}

public sealed class JsonNull : JsonNode
{
    public static readonly JsonNull Value = new();
    private JsonNull() { }
}

/// <summary>A number already in canonical text.</summary>
public sealed class JsonNum : JsonNode
{
    public string Text { get; }
    private JsonNum(string text) => Text = text;

    public static JsonNode Of(int value) => new JsonNum(value.ToString(CultureInfo.InvariantCulture));
    public static JsonNode Of(long value) => new JsonNum(value.ToString(CultureInfo.InvariantCulture));

    /// <summary>
    /// The shortest text that parses back to the same float32; -0 becomes 0. NaN and infinities have no
    /// JSON form and become null (callers report them as diagnostics).
    /// </summary>
    public static JsonNode Of(float value)
    {
        if (!float.IsFinite(value)) return JsonNull.Value;
        if (value == 0f) return new JsonNum("0");
        return new JsonNum(value.ToString("R", CultureInfo.InvariantCulture));
    }

    /// <summary>Doubles (measurements, not dat data) in shortest round-trip form.</summary>
    public static JsonNode Of(double value)
    {
        if (!double.IsFinite(value)) return JsonNull.Value;
        if (value == 0d) return new JsonNum("0");
        return new JsonNum(value.ToString("R", CultureInfo.InvariantCulture));
    }
}
