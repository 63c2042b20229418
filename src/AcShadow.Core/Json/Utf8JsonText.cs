using System.Globalization;
using System.Numerics;
using System.Text;

namespace AcShadow.Core.Json;

/// <summary>
/// Canonical JSON written straight to UTF-8 bytes, for the big files (BSP dumps) where building a
/// <see cref="JsonNode"/> tree first costs more than the data: the caller lays out the structure, this
/// writes the scalars exactly as <see cref="JsonNum"/> and <see cref="CanonicalJsonWriter"/> do
/// (shortest round-trip floats, -0 as 0, non-finite as null, the same string escapes).
/// </summary>
public sealed class Utf8JsonText
{
    private byte[] _buffer;
    private int _length;

    public Utf8JsonText(int capacity = 4096) => _buffer = new byte[Math.Max(16, capacity)];

    public byte[] ToArray() => _buffer.AsSpan(0, _length).ToArray();

    /// <summary>ASCII punctuation and fixed keys, as given.</summary>
    public Utf8JsonText Raw(string ascii)
    {
        Ensure(ascii.Length);
        foreach (var c in ascii) _buffer[_length++] = (byte)c;
        return this;
    }

    public Utf8JsonText Indent(int level)
    {
        Ensure(level * 2);
        _buffer.AsSpan(_length, level * 2).Fill((byte)' ');
        _length += level * 2;
        return this;
    }

    public Utf8JsonText Int(long value)
    {
        Ensure(24);
        value.TryFormat(_buffer.AsSpan(_length), out var written, default, CultureInfo.InvariantCulture);
        _length += written;
        return this;
    }

    public Utf8JsonText Float(float value)
    {
        if (!float.IsFinite(value)) return Raw("null");
        if (value == 0f) return Raw("0");
        Ensure(32);
        value.TryFormat(_buffer.AsSpan(_length), out var written, "R", CultureInfo.InvariantCulture);
        _length += written;
        return this;
    }

    public Utf8JsonText Vector(Vector3 v) => Raw("[").Float(v.X).Raw(", ").Float(v.Y).Raw(", ").Float(v.Z).Raw("]");

    public Utf8JsonText IntArray(IReadOnlyList<int> values)
    {
        Raw("[");
        for (var i = 0; i < values.Count; i++)
        {
            if (i > 0) Raw(", ");
            Int(values[i]);
        }
        return Raw("]");
    }

    /// <summary>A quoted string with <see cref="CanonicalJsonWriter"/>'s escapes.</summary>
    public Utf8JsonText String(string s)
    {
        var escaped = new StringBuilder(s.Length + 2);
        escaped.Append('"');
        foreach (var c in s)
        {
            switch (c)
            {
                case '"': escaped.Append("\\\""); break;
                case '\\': escaped.Append("\\\\"); break;
                case '\n': escaped.Append("\\n"); break;
                case '\r': escaped.Append("\\r"); break;
                case '\t': escaped.Append("\\t"); break;
                default:
                    if (c < 0x20) escaped.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                    else escaped.Append(c);
                    break;
            }
        }
        escaped.Append('"');
        var text = escaped.ToString();
        Ensure(Encoding.UTF8.GetMaxByteCount(text.Length));
        _length += Encoding.UTF8.GetBytes(text, _buffer.AsSpan(_length));
        return this;
    }

    private void Ensure(int more)
    {
        if (_length + more <= _buffer.Length) return;
        Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + more));
    }
}
