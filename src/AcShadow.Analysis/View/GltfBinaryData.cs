using System.Buffers;
using System.Buffers.Binary;
using System.Numerics;
using System.Text.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// A glTF file's one binary buffer and what indexes into it: each array is appended as its own bufferView
/// (tightly packed, 4-byte aligned since every element is a 4-byte float or unsigned int) with one accessor
/// over it, so accessor i reads bufferView i. Vertex arrays are converted to glTF's axes on the way in.
/// </summary>
internal sealed class GltfBinaryData
{
    private const int Float = 5126;
    private const int UnsignedInt = 5125;
    private const int ArrayBuffer = 34962;
    private const int ElementArrayBuffer = 34963;

    private readonly ArrayBufferWriter<byte> _bytes = new();
    private readonly List<View> _views = [];

    private sealed record View(int ByteOffset, int ByteLength, int Target, int ComponentType, int Count, string Type, Vector3? Min, Vector3? Max);

    public ReadOnlySpan<byte> Bytes => _bytes.WrittenSpan;
    public bool IsEmpty => _views.Count == 0;

    /// <summary>Vectors in dat axes as a VEC3 float accessor in glTF axes; <paramref name="bounds"/> adds its min and max (required on POSITION).</summary>
    public int AddVectors(IReadOnlyList<Vector3> dat, bool bounds)
    {
        var offset = _bytes.WrittenCount;
        var span = _bytes.GetSpan(dat.Count * 12)[..(dat.Count * 12)];
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        for (var i = 0; i < dat.Count; i++)
        {
            var v = GlbWriter.ToGltf(dat[i]);
            BinaryPrimitives.WriteSingleLittleEndian(span[(i * 12)..], v.X);
            BinaryPrimitives.WriteSingleLittleEndian(span[(i * 12 + 4)..], v.Y);
            BinaryPrimitives.WriteSingleLittleEndian(span[(i * 12 + 8)..], v.Z);
            min = new Vector3(Math.Min(min.X, v.X), Math.Min(min.Y, v.Y), Math.Min(min.Z, v.Z));
            max = new Vector3(Math.Max(max.X, v.X), Math.Max(max.Y, v.Y), Math.Max(max.Z, v.Z));
        }
        _bytes.Advance(span.Length);
        return Add(new View(offset, span.Length, ArrayBuffer, Float, dat.Count, "VEC3", bounds ? min : null, bounds ? max : null));
    }

    /// <summary>Triangle vertex indices as a SCALAR unsigned-int accessor.</summary>
    public int AddIndices(IReadOnlyList<int> indices)
    {
        var offset = _bytes.WrittenCount;
        var span = _bytes.GetSpan(indices.Count * 4)[..(indices.Count * 4)];
        for (var i = 0; i < indices.Count; i++) BinaryPrimitives.WriteUInt32LittleEndian(span[(i * 4)..], checked((uint)indices[i]));
        _bytes.Advance(span.Length);
        return Add(new View(offset, span.Length, ElementArrayBuffer, UnsignedInt, indices.Count, "SCALAR", null, null));
    }

    private int Add(View view)
    {
        _views.Add(view);
        return _views.Count - 1;
    }

    /// <summary>The "accessors", "bufferViews" and "buffers" properties (nothing when there is no data: glTF arrays may not be empty).</summary>
    public void WriteJson(Utf8JsonWriter json)
    {
        if (IsEmpty) return;
        json.WriteStartArray("accessors");
        for (var i = 0; i < _views.Count; i++)
        {
            var view = _views[i];
            json.WriteStartObject();
            json.WriteNumber("bufferView", i);
            json.WriteNumber("componentType", view.ComponentType);
            json.WriteNumber("count", view.Count);
            json.WriteString("type", view.Type);
            if (view.Min is { } min) GltfJson.WriteVector(json, "min", min);
            if (view.Max is { } max) GltfJson.WriteVector(json, "max", max);
            json.WriteEndObject();
        }
        json.WriteEndArray();

        json.WriteStartArray("bufferViews");
        foreach (var view in _views)
        {
            json.WriteStartObject();
            json.WriteNumber("buffer", 0);
            json.WriteNumber("byteOffset", view.ByteOffset);
            json.WriteNumber("byteLength", view.ByteLength);
            json.WriteNumber("target", view.Target);
            json.WriteEndObject();
        }
        json.WriteEndArray();

        json.WriteStartArray("buffers");
        json.WriteStartObject();
        json.WriteNumber("byteLength", _bytes.WrittenCount);
        json.WriteEndObject();
        json.WriteEndArray();
    }
}
