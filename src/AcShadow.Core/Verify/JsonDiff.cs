using System.Text;
using System.Text.Json;

namespace AcShadow.Core.Verify;

/// <summary>
/// Structural difference of two JSON documents, as JSONPaths with old and new values. Numbers compare by
/// their text (the formats are canonical, so equal values have equal text). Arrays whose items are all
/// objects with a distinct string "path" or "id" member are matched by that key
/// ("$.files[path=setups/0x020019FF.shadow.json].sha256"), so one inserted item does not shift every
/// later one; other arrays are compared position by position.
/// </summary>
public static class JsonDiff
{
    private const int MaxValueText = 120;
    private static readonly string[] KeyMembers = ["path", "id"];

    /// <summary>The UTF-8 byte-order mark, which a text reader (and so the fixtures library) skips.</summary>
    public static ReadOnlySpan<byte> Utf8Bom => [0xEF, 0xBB, 0xBF];

    /// <summary>
    /// The differences, or null when either side is not JSON. A leading byte-order mark is skipped, as the
    /// fixtures library (which reads text) skips it: a file the library reads is JSON here too.
    /// </summary>
    public static IReadOnlyList<JsonDifference>? Compare(byte[] oldJson, byte[] newJson)
    {
        JsonDocument? a = null, b = null;
        try
        {
            a = JsonDocument.Parse(WithoutBom(oldJson));
            b = JsonDocument.Parse(WithoutBom(newJson));
        }
        catch (JsonException)
        {
            a?.Dispose();
            return null;
        }
        using (a)
        using (b)
        {
            var differences = new List<JsonDifference>();
            try
            {
                Walk("$", a.RootElement, b.RootElement, differences);
            }
            // JSON that parses but holds text that is not UTF-8 (a damaged fixture): not comparable as JSON.
            catch (InvalidOperationException)
            {
                return null;
            }
            return differences;
        }
    }

    private static ReadOnlyMemory<byte> WithoutBom(byte[] json) => json.AsSpan().StartsWith(Utf8Bom) ? json.AsMemory(3) : json;

    private static void Walk(string path, JsonElement a, JsonElement b, List<JsonDifference> diffs)
    {
        if (a.ValueKind == JsonValueKind.Object && b.ValueKind == JsonValueKind.Object)
        {
            var bMembers = b.EnumerateObject().ToDictionary(p => p.Name, p => p.Value, StringComparer.Ordinal);
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (var p in a.EnumerateObject())
            {
                seen.Add(p.Name);
                var child = Member(path, p.Name);
                if (bMembers.TryGetValue(p.Name, out var bv)) Walk(child, p.Value, bv, diffs);
                else diffs.Add(new JsonDifference(child, Text(p.Value), null));
            }
            foreach (var p in b.EnumerateObject().Where(p => !seen.Contains(p.Name)))
                diffs.Add(new JsonDifference(Member(path, p.Name), null, Text(p.Value)));
            return;
        }
        if (a.ValueKind == JsonValueKind.Array && b.ValueKind == JsonValueKind.Array)
        {
            var key = SharedKey(a, b);
            if (key is null) WalkPositional(path, a, b, diffs);
            else WalkKeyed(path, key, a, b, diffs);
            return;
        }
        if (!SameScalar(a, b)) diffs.Add(new JsonDifference(path, Text(a), Text(b)));
    }

    private static void WalkPositional(string path, JsonElement a, JsonElement b, List<JsonDifference> diffs)
    {
        var aItems = a.EnumerateArray().ToArray();
        var bItems = b.EnumerateArray().ToArray();
        for (var i = 0; i < Math.Max(aItems.Length, bItems.Length); i++)
        {
            var child = $"{path}[{i}]";
            if (i >= aItems.Length) diffs.Add(new JsonDifference(child, null, Text(bItems[i])));
            else if (i >= bItems.Length) diffs.Add(new JsonDifference(child, Text(aItems[i]), null));
            else Walk(child, aItems[i], bItems[i], diffs);
        }
    }

    private static void WalkKeyed(string path, string key, JsonElement a, JsonElement b, List<JsonDifference> diffs)
    {
        var bItems = b.EnumerateArray().ToDictionary(e => e.GetProperty(key).GetString()!, StringComparer.Ordinal);
        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var item in a.EnumerateArray())
        {
            var k = item.GetProperty(key).GetString()!;
            seen.Add(k);
            var child = $"{path}[{key}={k}]";
            if (bItems.TryGetValue(k, out var other)) Walk(child, item, other, diffs);
            else diffs.Add(new JsonDifference(child, Text(item), null));
        }
        foreach (var item in b.EnumerateArray())
        {
            var k = item.GetProperty(key).GetString()!;
            if (!seen.Contains(k)) diffs.Add(new JsonDifference($"{path}[{key}={k}]", null, Text(item)));
        }
    }

    /// <summary>"path" or "id" when every item of both arrays is an object whose such member is a distinct string.</summary>
    private static string? SharedKey(JsonElement a, JsonElement b)
    {
        var items = a.EnumerateArray().Concat(b.EnumerateArray()).ToArray();
        if (items.Length == 0 || items.Any(i => i.ValueKind != JsonValueKind.Object)) return null;
        foreach (var key in KeyMembers)
        {
            if (!items.All(i => i.TryGetProperty(key, out var v) && v.ValueKind == JsonValueKind.String)) continue;
            if (Distinct(a, key) && Distinct(b, key)) return key;
        }
        return null;
    }

    private static bool Distinct(JsonElement array, string key)
    {
        var keys = array.EnumerateArray().Select(i => i.GetProperty(key).GetString()).ToArray();
        return keys.Distinct(StringComparer.Ordinal).Count() == keys.Length;
    }

    private static bool SameScalar(JsonElement a, JsonElement b)
    {
        if (a.ValueKind != b.ValueKind) return false;
        return a.ValueKind switch
        {
            JsonValueKind.String => a.GetString() == b.GetString(),
            JsonValueKind.Number => a.GetRawText() == b.GetRawText(),
            _ => true,
        };
    }

    private static string Member(string path, string name) =>
        name.Length > 0 && name.All(c => char.IsAsciiLetterOrDigit(c) || c == '_') && !char.IsAsciiDigit(name[0])
            ? $"{path}.{name}"
            : $"{path}[{QuotedName(name)}]";

    /// <summary>A member name as a JSON string literal (no reflection: the tool is published ahead-of-time).</summary>
    private static string QuotedName(string name)
    {
        using var stream = new MemoryStream();
        using (var writer = new Utf8JsonWriter(stream)) writer.WriteStringValue(name);
        return System.Text.Encoding.UTF8.GetString(stream.ToArray());
    }

    /// <summary>The value as compact JSON, shortened for one-line reports.</summary>
    private static string Text(JsonElement e)
    {
        var text = e.ValueKind is JsonValueKind.Object or JsonValueKind.Array ? Compact(e) : e.GetRawText();
        return text.Length <= MaxValueText ? text : text[..(MaxValueText - 1)] + "…";
    }

    private static string Compact(JsonElement e)
    {
        using var stream = new MemoryStream();
        using (var writer = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = false, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
            e.WriteTo(writer);
        return Encoding.UTF8.GetString(stream.ToArray());
    }
}
