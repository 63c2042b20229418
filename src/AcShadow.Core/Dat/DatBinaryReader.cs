using System.Buffers.Binary;
using System.Numerics;

namespace AcShadow.Core.Dat;

/// <summary>
/// Little-endian reader over one object's bytes (block chain already followed).
/// Every read is bounds-checked so a truncated object is a <see cref="DatFormatException"/>, never garbage.
/// <paramref name="what"/> prefixes its messages; leave it null when the caller names the object itself.
/// </summary>
public sealed class DatBinaryReader(ReadOnlyMemory<byte> data, string? what = null)
{
    private readonly string _prefix = what is null ? "" : what + ": ";
    private readonly ReadOnlyMemory<byte> _data = data;
    private int _offset;

    public int Offset => _offset;
    public int Remaining => _data.Length - _offset;

    private ReadOnlySpan<byte> Take(int count)
    {
        if (count < 0 || _offset + count > _data.Length)
            throw new DatFormatException($"{_prefix}needs {count} more byte(s) at offset {_offset}, but only {Remaining} remain (truncated or not this object type).");
        var span = _data.Span.Slice(_offset, count);
        _offset += count;
        return span;
    }

    public byte ReadByte() => Take(1)[0];
    public short ReadInt16() => BinaryPrimitives.ReadInt16LittleEndian(Take(2));
    public ushort ReadUInt16() => BinaryPrimitives.ReadUInt16LittleEndian(Take(2));
    public int ReadInt32() => BinaryPrimitives.ReadInt32LittleEndian(Take(4));
    public uint ReadUInt32() => BinaryPrimitives.ReadUInt32LittleEndian(Take(4));
    public float ReadSingle() => BinaryPrimitives.ReadSingleLittleEndian(Take(4));
    public byte[] ReadBytes(int count) => Take(count).ToArray();

    /// <summary>Steps over bytes the decoder does not keep (bounds-checked like a read, no copy).</summary>
    public void Skip(int count) => Take(count);

    public Vector3 ReadVector3() => new(ReadSingle(), ReadSingle(), ReadSingle());

    /// <summary>Dat quaternions are stored W, X, Y, Z; System.Numerics wants X, Y, Z, W.</summary>
    public Quaternion ReadQuaternion()
    {
        var w = ReadSingle();
        var x = ReadSingle();
        var y = ReadSingle();
        var z = ReadSingle();
        return new Quaternion(x, y, z, w);
    }

    public Plane ReadPlane() => new(ReadVector3(), ReadSingle());

    /// <summary>1, 2 or 4 bytes: 0x80 clear → one byte; 0x80 set, 0x40 clear → two; both set → four.</summary>
    public uint ReadCompressedUInt32()
    {
        var b0 = ReadByte();
        if ((b0 & 0x80) == 0) return b0;
        var b1 = ReadByte();
        if ((b0 & 0x40) == 0) return (uint)(((b0 & 0x7F) << 8) | b1);
        var low = ReadUInt16();
        return (uint)(((((b0 & 0x3F) << 8) | b1) << 16) | low);
    }

    /// <summary>Skips padding so the next read starts at a multiple of <paramref name="alignment"/>.</summary>
    public void Align(int alignment)
    {
        var delta = _offset % alignment;
        if (delta > 0) Take(alignment - delta);
    }

    /// <summary>Reads a count and refuses one larger than the bytes left could hold (corrupt data guard).</summary>
    public int ReadCount(uint count, int minBytesEach, string field)
    {
        if (count > int.MaxValue || (long)count * minBytesEach > Remaining)
            throw new DatFormatException($"{_prefix}{field} count {count} cannot fit in the {Remaining} byte(s) left.");
        return (int)count;
    }
}
