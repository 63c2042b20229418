using System.Text;

namespace AcShadow.Core.Json;

/// <summary>
/// Writes a <see cref="JsonNode"/> tree in acshadow's canonical layout: 2-space indent, LF, final newline,
/// keys in insertion order, and small values on one line — arrays of scalars (vectors, id lists) and
/// objects of at most five scalar or scalar-array members (quaternions, planes, spheres, vertices).
/// </summary>
public static class CanonicalJsonWriter
{
    private const int MaxInlineMembers = 5;

    /// <summary>The canonical text: the characters of <see cref="WriteUtf8"/>'s bytes.</summary>
    public static string Write(JsonNode root) => Encoding.UTF8.GetString(WriteUtf8(root));

    /// <summary>Straight to UTF-8 in the thread's reused buffer (no StringBuilder, no intermediate string).</summary>
    public static byte[] WriteUtf8(JsonNode root) => Utf8JsonText.Build(root, static (t, root) =>
    {
        WriteNode(t, root, 0);
        t.Raw("\n"u8);
    });

    private static void WriteNode(Utf8JsonText t, JsonNode node, int indent)
    {
        switch (node)
        {
            case JsonObj obj when obj.Members.Count == 0: t.Raw("{}"u8); break;
            case JsonObj obj when IsInline(obj):
                t.Raw("{"u8);
                for (var i = 0; i < obj.Members.Count; i++)
                {
                    if (i > 0) t.Raw(", "u8);
                    t.String(obj.Members[i].Key).Raw(": "u8);
                    WriteNode(t, obj.Members[i].Value, indent);
                }
                t.Raw("}"u8);
                break;
            case JsonObj obj:
                t.Raw("{\n"u8);
                for (var i = 0; i < obj.Members.Count; i++)
                {
                    t.Indent(indent + 1).String(obj.Members[i].Key).Raw(": "u8);
                    WriteNode(t, obj.Members[i].Value, indent + 1);
                    t.Raw(i < obj.Members.Count - 1 ? ",\n"u8 : "\n"u8);
                }
                t.Indent(indent).Raw("}"u8);
                break;
            case JsonArr arr when arr.Items.Count == 0: t.Raw("[]"u8); break;
            case JsonArr arr when AllScalar(arr):
                t.Raw("["u8);
                for (var i = 0; i < arr.Items.Count; i++)
                {
                    if (i > 0) t.Raw(", "u8);
                    WriteNode(t, arr.Items[i], indent);
                }
                t.Raw("]"u8);
                break;
            case JsonArr arr:
                t.Raw("[\n"u8);
                for (var i = 0; i < arr.Items.Count; i++)
                {
                    t.Indent(indent + 1);
                    WriteNode(t, arr.Items[i], indent + 1);
                    t.Raw(i < arr.Items.Count - 1 ? ",\n"u8 : "\n"u8);
                }
                t.Indent(indent).Raw("]"u8);
                break;
            case JsonStr s: t.String(s.Value); break;
            case JsonNum n: t.Raw(n.Text); break;
            case JsonBool b: t.Raw(b.Value ? "true"u8 : "false"u8); break;
            case JsonNull: t.Raw("null"u8); break;
            default: throw new ArgumentException($"unknown JSON node {node.GetType().Name}");
        }
    }

    private static bool IsScalar(JsonNode n) => n is JsonStr or JsonNum or JsonBool or JsonNull;

    private static bool AllScalar(JsonArr arr)
    {
        foreach (var item in arr.Items)
            if (!IsScalar(item)) return false;
        return true;
    }

    private static bool IsInline(JsonObj obj)
    {
        if (obj.Members.Count > MaxInlineMembers) return false;
        foreach (var (_, value) in obj.Members)
            if (!IsScalar(value) && !(value is JsonArr a && a.Items.Count <= 4 && AllScalar(a))) return false;
        return true;
    }
}
