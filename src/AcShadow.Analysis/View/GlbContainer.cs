using System.Buffers.Binary;

namespace AcShadow.Analysis.View;

/// <summary>
/// The binary glTF 2.0 container: a 12-byte header (magic "glTF", version 2, total length), then a JSON chunk
/// padded with spaces to a multiple of 4 bytes, then (when there is binary data) a BIN chunk padded with zeros,
/// so every chunk starts 4-byte aligned as the GLB layout requires. All integers little-endian.
/// </summary>
public static class GlbContainer
{
    public const uint Magic = 0x46546C67; // "glTF"
    public const uint Version = 2;
    public const uint JsonChunk = 0x4E4F534A; // "JSON"
    public const uint BinChunk = 0x004E4942; // "BIN\0"

    private const int HeaderLength = 12;
    private const int ChunkHeaderLength = 8;

    public static byte[] Pack(ReadOnlySpan<byte> json, ReadOnlySpan<byte> bin)
    {
        var jsonLength = Padded(json.Length);
        var binLength = Padded(bin.Length);
        var total = HeaderLength + ChunkHeaderLength + jsonLength + (bin.IsEmpty ? 0 : ChunkHeaderLength + binLength);
        var bytes = new byte[total];
        var span = bytes.AsSpan();
        BinaryPrimitives.WriteUInt32LittleEndian(span, Magic);
        BinaryPrimitives.WriteUInt32LittleEndian(span[4..], Version);
        BinaryPrimitives.WriteUInt32LittleEndian(span[8..], (uint)total);
        var at = WriteChunk(span, HeaderLength, JsonChunk, json, jsonLength, (byte)' ');
        if (!bin.IsEmpty) WriteChunk(span, at, BinChunk, bin, binLength, 0);
        return bytes;
    }

    private static int Padded(int length) => (length + 3) & ~3;

    private static int WriteChunk(Span<byte> file, int at, uint type, ReadOnlySpan<byte> data, int paddedLength, byte pad)
    {
        BinaryPrimitives.WriteUInt32LittleEndian(file[at..], (uint)paddedLength);
        BinaryPrimitives.WriteUInt32LittleEndian(file[(at + 4)..], type);
        var body = file.Slice(at + ChunkHeaderLength, paddedLength);
        data.CopyTo(body);
        body[data.Length..].Fill(pad);
        return at + ChunkHeaderLength + paddedLength;
    }
}
