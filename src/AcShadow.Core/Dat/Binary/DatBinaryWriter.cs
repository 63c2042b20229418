using System.Buffers.Binary;
using System.Numerics;
using AcShadow.Fixtures.Geometry;

namespace AcShadow.Core.Dat.Binary;

/// <summary>Little-endian writer that mirrors <see cref="DatBinaryReader"/> field for field.</summary>
public sealed class DatBinaryWriter
{
    private readonly MemoryStream _stream = new();

    public int Offset => (int)_stream.Length;

    public byte[] ToArray() => _stream.ToArray();

    private void Put(ReadOnlySpan<byte> bytes) => _stream.Write(bytes);

    public void WriteByte(byte value) => _stream.WriteByte(value);

    public void WriteInt16(short value) { Span<byte> b = stackalloc byte[2]; BinaryPrimitives.WriteInt16LittleEndian(b, value); Put(b); }
    public void WriteUInt16(ushort value) { Span<byte> b = stackalloc byte[2]; BinaryPrimitives.WriteUInt16LittleEndian(b, value); Put(b); }
    public void WriteInt32(int value) { Span<byte> b = stackalloc byte[4]; BinaryPrimitives.WriteInt32LittleEndian(b, value); Put(b); }
    public void WriteUInt32(uint value) { Span<byte> b = stackalloc byte[4]; BinaryPrimitives.WriteUInt32LittleEndian(b, value); Put(b); }
    public void WriteSingle(float value) { Span<byte> b = stackalloc byte[4]; BinaryPrimitives.WriteSingleLittleEndian(b, value); Put(b); }
    public void WriteBytes(ReadOnlySpan<byte> bytes) => Put(bytes);

    public void WriteVector3(Vector3 v) { WriteSingle(v.X); WriteSingle(v.Y); WriteSingle(v.Z); }

    /// <summary>Stored W, X, Y, Z (see <see cref="DatBinaryReader.ReadQuaternion"/>).</summary>
    public void WriteQuaternion(Quaternion q) { WriteSingle(q.W); WriteSingle(q.X); WriteSingle(q.Y); WriteSingle(q.Z); }

    public void WritePlane(Plane p) { WriteVector3(p.Normal); WriteSingle(p.D); }

    public void WriteFrame(Frame f) { WriteVector3(f.Position); WriteQuaternion(f.Rotation); }

    public void WriteCompressedUInt32(uint value)
    {
        if (value < 0x80) { WriteByte((byte)value); return; }
        if (value < 0x4000) { WriteByte((byte)(0x80 | (value >> 8))); WriteByte((byte)value); return; }
        if (value >= 0x40000000) throw new ArgumentOutOfRangeException(nameof(value), value, "compressed uint holds at most 30 bits");
        WriteByte((byte)(0xC0 | (value >> 24)));
        WriteByte((byte)(value >> 16));
        WriteUInt16((ushort)value);
    }

    /// <summary>
    /// <see cref="DatBinaryReader.ReadPackedDataId"/>'s layout: the short form for offsets up to 0x7FFF (the
    /// readers' limit), the long form up to 0x3FFFFFFF.
    /// </summary>
    public void WritePackedDataId(uint id, uint knownType)
    {
        if (id < knownType || id - knownType > 0x3FFFFFFF)
            throw new ArgumentOutOfRangeException(nameof(id), id, $"a packed data id holds an offset of 0 to 0x3FFFFFFF from 0x{knownType:X8}");
        var offset = id - knownType;
        if (offset <= 0x7FFF) { WriteUInt16((ushort)offset); return; }
        WriteUInt16((ushort)(0x8000 | (offset >> 16)));
        WriteUInt16((ushort)offset);
    }

    public void Align(int alignment)
    {
        while (Offset % alignment != 0) WriteByte(0);
    }
}
