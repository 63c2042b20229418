using System.Buffers.Binary;
using System.Numerics;
using AcShadow.Fixtures.Geometry;
using System.Runtime.InteropServices;

namespace AcShadow.Core.Dat.Binary;

/// <summary>
/// Little-endian reader over one object's bytes (block chain already followed).
/// Every read is bounds-checked so a truncated object is a <see cref="DatFormatException"/>, never garbage.
/// <paramref name="what"/> prefixes its messages; leave it null when the caller names the object itself.
/// </summary>
public sealed class DatBinaryReader
{
    private readonly string _prefix;

    // The bytes as array, start and length: a span is made per read, and ReadOnlyMemory.Span costs
    // more than the read itself (a GfxObj is mostly 4-byte reads).
    private readonly byte[] _array;
    private readonly int _start;
    private readonly int _length;
    private int _offset;

    public DatBinaryReader(ReadOnlyMemory<byte> data, string? what = null)
    {
        _prefix = what is null ? "" : what + ": ";
        var segment = MemoryMarshal.TryGetArray(data, out var array) ? array : new ArraySegment<byte>(data.ToArray());
        (_array, _start, _length) = (segment.Array!, segment.Offset, segment.Count);
    }

    public int Offset => _offset;
    public int Remaining => _length - _offset;

    private ReadOnlySpan<byte> Take(int count)
    {
        if ((uint)count > (uint)(_length - _offset))
            throw new DatFormatException($"{_prefix}needs {count} more byte(s) at offset {_offset}, but only {Remaining} remain (truncated or not this object type).");
        var span = new ReadOnlySpan<byte>(_array, _start + _offset, count);
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

    /// <summary>The next <paramref name="count"/> bytes without moving past them (bounds-checked like a read).</summary>
    public ReadOnlySpan<byte> Peek(int count)
    {
        var span = Take(count);
        _offset -= count;
        return span;
    }

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

    /// <summary>A Frame: origin, then orientation.</summary>
    public Frame ReadFrame() => new(ReadVector3(), ReadQuaternion());

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

    /// <summary>
    /// A data id of a known type, packed as its offset from <paramref name="knownType"/>: one ushort when the
    /// top bit is clear; else that ushort's low 14 bits are the offset's bits 16..29 and a second ushort
    /// holds bits 0..15 (retail's packed data id; DatReaderWriter and ACE read it so).
    /// </summary>
    public uint ReadPackedDataId(uint knownType)
    {
        var first = ReadUInt16();
        if ((first & 0x8000) == 0) return knownType + first;
        var low = ReadUInt16();
        return knownType + ((uint)(first & 0x3FFF) << 16 | low);
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
