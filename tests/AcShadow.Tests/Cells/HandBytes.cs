using System.Buffers.Binary;
using System.Text;

namespace AcShadow.Tests.Cells;

/// <summary>
/// Little-endian bytes put down one field at a time, independent of the dat layer's writer, so a layout
/// test's expected bytes come from the published layout and not from the code under test.
/// </summary>
internal sealed class HandBytes
{
    private readonly List<byte> _bytes = [];

    public int Length => _bytes.Count;
    public byte[] ToArray() => [.. _bytes];

    public HandBytes U8(byte v) { _bytes.Add(v); return this; }
    public HandBytes U16(ushort v) { Span<byte> b = stackalloc byte[2]; BinaryPrimitives.WriteUInt16LittleEndian(b, v); _bytes.AddRange(b.ToArray()); return this; }
    public HandBytes I16(short v) => U16((ushort)v);
    public HandBytes U32(uint v) { Span<byte> b = stackalloc byte[4]; BinaryPrimitives.WriteUInt32LittleEndian(b, v); _bytes.AddRange(b.ToArray()); return this; }
    public HandBytes I32(int v) => U32((uint)v);
    public HandBytes F32(float v) => U32(BitConverter.SingleToUInt32Bits(v));
    public HandBytes Floats(params float[] v) { foreach (var f in v) F32(f); return this; }

    /// <summary>A BSP tag: four ASCII letters read as a little-endian uint, so "LEAF" is stored F, A, E, L.</summary>
    public HandBytes Tag(string tag)
    {
        var ascii = Encoding.ASCII.GetBytes(tag);
        for (var i = 3; i >= 0; i--) _bytes.Add(ascii[i]);
        return this;
    }

    public HandBytes Zeros(int count) { for (var i = 0; i < count; i++) _bytes.Add(0); return this; }
}
