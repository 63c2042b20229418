using System.Globalization;
using System.Numerics;
using System.Runtime.CompilerServices;
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
    /// <summary>A reused buffer larger than this is let go, so a thread keeps at most this much between files.</summary>
    private const int MaxKeptBytes = 4 << 20;

    /// <summary>Each thread's spare text for <see cref="Build"/>; null while in use, so a nested build gets its own.</summary>
    [ThreadStatic] private static Utf8JsonText? t_spare;

    private byte[] _buffer;
    private int _length;

    public Utf8JsonText(int capacity = 4096) => _buffer = new byte[Math.Max(16, capacity)];

    /// <summary>
    /// The bytes <paramref name="write"/> lays out, written into this thread's reused buffer: one array per
    /// file (the result), not a growing buffer and its copy, which for BSP dumps are mostly large-object-heap
    /// arrays that only a gen2 collection frees.
    /// </summary>
    public static byte[] Build<TState>(TState state, Action<Utf8JsonText, TState> write) =>
        Lend(state, write, static bytes => bytes.ToArray());

    /// <summary>
    /// As <see cref="Build"/>, but the bytes are lent to <paramref name="use"/> straight from this thread's
    /// buffer instead of copied into an array of their own; they are valid only until it returns. For a
    /// batch, which writes and hashes each file at once: its BSP dumps, hundreds of KB each on a retail
    /// dat, would otherwise each be a new large-object-heap array.
    /// </summary>
    public static TResult Lend<TState, TResult>(TState state, Action<Utf8JsonText, TState> write, Func<ReadOnlyMemory<byte>, TResult> use)
    {
        var text = t_spare ?? new Utf8JsonText(64 * 1024);
        t_spare = null;
        text._length = 0;
        try
        {
            write(text, state);
            return use(text._buffer.AsMemory(0, text._length));
        }
        finally
        {
            if (text._buffer.Length <= MaxKeptBytes) t_spare = text;
        }
    }

    public byte[] ToArray() => _buffer.AsSpan(0, _length).ToArray();

    /// <summary>Bytes written so far.</summary>
    public int Length => _length;

    /// <summary>Writes the text so far to <paramref name="destination"/> and starts empty again (chunked output).</summary>
    public Utf8JsonText MoveTo(Stream destination)
    {
        destination.Write(_buffer, 0, _length);
        _length = 0;
        return this;
    }

    /// <summary>ASCII punctuation and fixed keys, as given.</summary>
    public Utf8JsonText Raw(string ascii)
    {
        Ensure(ascii.Length);
        foreach (var c in ascii) _buffer[_length++] = (byte)c;
        return this;
    }

    /// <summary>
    /// Punctuation and fixed keys already in UTF-8 (u8 literals): one copy, no per-character loop. Inlined,
    /// so a literal's copy is unrolled at its call site (a BSP dump is mostly short literals).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Utf8JsonText Raw(ReadOnlySpan<byte> utf8)
    {
        Ensure(utf8.Length);
        utf8.CopyTo(_buffer.AsSpan(_length));
        _length += utf8.Length;
        return this;
    }

    /// <summary>Text already in canonical form (a rendered head), as UTF-8.</summary>
    public Utf8JsonText Utf8(string text)
    {
        Ensure(Encoding.UTF8.GetMaxByteCount(text.Length));
        _length += Encoding.UTF8.GetBytes(text, _buffer.AsSpan(_length));
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
        // Ids, counts and indices: nearly all below 10,000, written without the general formatter.
        if ((ulong)value < 10_000)
        {
            var v = (int)value;
            var digits = v < 10 ? 1 : v < 100 ? 2 : v < 1000 ? 3 : 4;
            var end = _length + digits;
            for (var i = end - 1; i >= _length; i--, v /= 10) _buffer[i] = (byte)('0' + v % 10);
            _length = end;
            return this;
        }
        value.TryFormat(_buffer.AsSpan(_length), out var written, default, CultureInfo.InvariantCulture);
        _length += written;
        return this;
    }

    public Utf8JsonText Float(float value)
    {
        if (!float.IsFinite(value)) return Raw("null"u8);
        if (value == 0f) return Raw("0"u8);
        Ensure(32);
        _length += FloatTextCache.Current.Write(value, _buffer.AsSpan(_length));
        return this;
    }

    public Utf8JsonText Vector(Vector3 v) => Raw("["u8).Float(v.X).Raw(", "u8).Float(v.Y).Raw(", "u8).Float(v.Z).Raw("]"u8);

    public Utf8JsonText IntArray(IReadOnlyList<int> values)
    {
        Raw("["u8);
        for (var i = 0; i < values.Count; i++)
        {
            if (i > 0) Raw(", "u8);
            Int(values[i]);
        }
        return Raw("]"u8);
    }

    /// <summary>A quoted string with <see cref="CanonicalJsonWriter"/>'s escapes.</summary>
    public Utf8JsonText String(string s) => String(s.AsSpan());

    /// <summary>
    /// As <see cref="String(string)"/>. The runs between escapes are encoded whole, so a surrogate pair is
    /// never split (escapes are all ASCII) and a lone surrogate becomes U+FFFD as it does for the whole string.
    /// </summary>
    public Utf8JsonText String(ReadOnlySpan<char> s)
    {
        Raw("\""u8);
        var start = 0;
        for (var i = 0; i < s.Length; i++)
        {
            var c = s[i];
            if (c >= 0x20 && c != '"' && c != '\\') continue;
            Plain(s[start..i]);
            switch (c)
            {
                case '"': Raw("\\\""u8); break;
                case '\\': Raw("\\\\"u8); break;
                case '\n': Raw("\\n"u8); break;
                case '\r': Raw("\\r"u8); break;
                case '\t': Raw("\\t"u8); break;
                default:
                    Raw("\\u"u8);
                    Ensure(4);
                    ((int)c).TryFormat(_buffer.AsSpan(_length), out var written, "x4", CultureInfo.InvariantCulture);
                    _length += written;
                    break;
            }
            start = i + 1;
        }
        Plain(s[start..]);
        return Raw("\""u8);
    }

    private void Plain(ReadOnlySpan<char> run)
    {
        if (run.IsEmpty) return;
        Ensure(Encoding.UTF8.GetMaxByteCount(run.Length));
        _length += Encoding.UTF8.GetBytes(run, _buffer.AsSpan(_length));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Ensure(int more)
    {
        if (_length + more > _buffer.Length) Grow(more);
    }

    private void Grow(int more) => Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + more));
}
