using System.Globalization;

namespace AcShadow.Core.Json;

/// <summary>
/// Each thread's recently written floats and their shortest round-trip ("R") text. Geometry repeats its
/// numbers (shared coordinates, axis-aligned normals, equal plane distances) and formatting a float was
/// the costliest single step of writing a BSP dump; a hit is a 16-byte copy. Direct-mapped: a miss
/// formats and replaces the slot, so the text is always exactly what <see cref="float.TryFormat(Span{byte}, out int, ReadOnlySpan{char}, IFormatProvider?)"/>
/// gives, whatever was written before or on which thread.
/// </summary>
internal sealed class FloatTextCache
{
    private const int SlotBits = 12;

    /// <summary>The longest "R" text of a finite float is 15 bytes ("-1.1754944E-38" is 14).</summary>
    private const int SlotBytes = 16;

    /// <summary>No finite float has these bits (they are a NaN), so an unused slot never matches.</summary>
    private const uint Empty = uint.MaxValue;

    [ThreadStatic] private static FloatTextCache? t_current;

    private readonly uint[] _keys = new uint[1 << SlotBits];
    private readonly byte[] _lengths = new byte[1 << SlotBits];
    private readonly byte[] _text = new byte[(1 << SlotBits) * SlotBytes];

    private FloatTextCache() => Array.Fill(_keys, Empty);

    public static FloatTextCache Current => t_current ??= new FloatTextCache();

    /// <summary>
    /// Writes the text of <paramref name="value"/> into <paramref name="destination"/> (at least 32 bytes)
    /// and returns its length; bytes past that length may be overwritten.
    /// </summary>
    public int Write(float value, Span<byte> destination)
    {
        if (!float.IsFinite(value)) return Format(value, destination);
        var bits = BitConverter.SingleToUInt32Bits(value);
        var slot = (int)((bits * 0x9E3779B1u) >> (32 - SlotBits));
        var text = _text.AsSpan(slot * SlotBytes, SlotBytes);
        if (_keys[slot] != bits)
        {
            if (!value.TryFormat(text, out var length, "R", CultureInfo.InvariantCulture)) return Format(value, destination);
            _keys[slot] = bits;
            _lengths[slot] = (byte)length;
        }
        // The whole slot in one 16-byte copy (the caller leaves room); only its length counts.
        text.CopyTo(destination);
        return _lengths[slot];
    }

    private static int Format(float value, Span<byte> destination)
    {
        value.TryFormat(destination, out var written, "R", CultureInfo.InvariantCulture);
        return written;
    }
}
