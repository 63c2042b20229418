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

    public static string Write(JsonNode root)
    {
        var sb = new StringBuilder();
        WriteNode(sb, root, 0);
        sb.Append('\n');
        return sb.ToString();
    }

    public static byte[] WriteUtf8(JsonNode root) => new UTF8Encoding(false).GetBytes(Write(root));

    private static void WriteNode(StringBuilder sb, JsonNode node, int indent)
    {
        switch (node)
        {
            case JsonObj obj when obj.Members.Count == 0: sb.Append("{}"); break;
            case JsonObj obj when IsInline(obj):
                sb.Append('{');
                for (var i = 0; i < obj.Members.Count; i++)
                {
                    if (i > 0) sb.Append(", ");
                    WriteString(sb, obj.Members[i].Key);
                    sb.Append(": ");
                    WriteNode(sb, obj.Members[i].Value, indent);
                }
                sb.Append('}');
                break;
            case JsonObj obj:
                sb.Append("{\n");
                for (var i = 0; i < obj.Members.Count; i++)
                {
                    Indent(sb, indent + 1);
                    WriteString(sb, obj.Members[i].Key);
                    sb.Append(": ");
                    WriteNode(sb, obj.Members[i].Value, indent + 1);
                    sb.Append(i < obj.Members.Count - 1 ? ",\n" : "\n");
                }
                Indent(sb, indent);
                sb.Append('}');
                break;
            case JsonArr arr when arr.Items.Count == 0: sb.Append("[]"); break;
            case JsonArr arr when arr.Items.All(IsScalar):
                sb.Append('[');
                for (var i = 0; i < arr.Items.Count; i++)
                {
                    if (i > 0) sb.Append(", ");
                    WriteNode(sb, arr.Items[i], indent);
                }
                sb.Append(']');
                break;
            case JsonArr arr:
                sb.Append("[\n");
                for (var i = 0; i < arr.Items.Count; i++)
                {
                    Indent(sb, indent + 1);
                    WriteNode(sb, arr.Items[i], indent + 1);
                    sb.Append(i < arr.Items.Count - 1 ? ",\n" : "\n");
                }
                Indent(sb, indent);
                sb.Append(']');
                break;
            case JsonStr s: WriteString(sb, s.Value); break;
            case JsonNum n: sb.Append(n.Text); break;
            case JsonBool b: sb.Append(b.Value ? "true" : "false"); break;
            case JsonNull: sb.Append("null"); break;
            default: throw new ArgumentException($"unknown JSON node {node.GetType().Name}");
        }
    }

    private static bool IsScalar(JsonNode n) => n is JsonStr or JsonNum or JsonBool or JsonNull;

    private static bool IsInline(JsonObj obj) =>
        obj.Members.Count <= MaxInlineMembers
        && obj.Members.All(m => IsScalar(m.Value) || (m.Value is JsonArr a && a.Items.All(IsScalar) && a.Items.Count <= 4));

    private static void Indent(StringBuilder sb, int level) => sb.Append(' ', level * 2);

    private static void WriteString(StringBuilder sb, string s)
    {
        sb.Append('"');
        foreach (var c in s)
        {
            switch (c)
            {
                case '"': sb.Append("\\\""); break;
                case '\\': sb.Append("\\\\"); break;
                case '\n': sb.Append("\\n"); break;
                case '\r': sb.Append("\\r"); break;
                case '\t': sb.Append("\\t"); break;
                default:
                    if (c < 0x20) sb.Append("\\u").Append(((int)c).ToString("x4", System.Globalization.CultureInfo.InvariantCulture));
                    else sb.Append(c);
                    break;
            }
        }
        sb.Append('"');
    }
}
