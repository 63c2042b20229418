using AcShadow.Core.Dat.Binary;
using AcShadow.Fixtures.Bsp;

namespace AcShadow.Core.Dat.Objects;

/// <summary>
/// A GfxObj polygon: vertex ids into the GfxObj's vertex array. UV index lists are present unless the
/// stippling says NoPos / NoNeg (negative UVs only for Clockwise polygons). They are drawing only: reading steps
/// over them, as it steps over the vertices' normals and UVs, so a polygon read from a dat has none (a byte array
/// each: 33 of the 566 MB a batch of the scale dat decoded); writing emits what it is given, zeros where it has none.
/// </summary>
public sealed record Polygon(
    Stippling Stippling,
    SidesType SidesType,
    short PosSurface,
    short NegSurface,
    IReadOnlyList<short> VertexIds,
    IReadOnlyList<byte> PosUVIndices,
    IReadOnlyList<byte> NegUVIndices)
{
    public static Polygon Read(DatBinaryReader r)
    {
        var count = r.ReadByte();
        var stippling = (Stippling)r.ReadByte();
        var sides = (SidesType)r.ReadInt32();
        var pos = r.ReadInt16();
        var neg = r.ReadInt16();
        var ids = new short[count];
        for (var i = 0; i < count; i++) ids[i] = r.ReadInt16();
        if (!stippling.HasFlag(Stippling.NoPos)) r.Skip(count);
        if (!stippling.HasFlag(Stippling.NoNeg) && sides == SidesType.Clockwise) r.Skip(count);
        return new Polygon(stippling, sides, pos, neg, ids, [], []);
    }

    public void Write(DatBinaryWriter w)
    {
        if (VertexIds.Count > byte.MaxValue) throw new InvalidOperationException($"a polygon holds at most 255 vertices, not {VertexIds.Count}");
        w.WriteByte((byte)VertexIds.Count);
        w.WriteByte((byte)Stippling);
        w.WriteInt32((int)SidesType);
        w.WriteInt16(PosSurface);
        w.WriteInt16(NegSurface);
        foreach (var id in VertexIds) w.WriteInt16(id);
        if (!Stippling.HasFlag(Stippling.NoPos)) WriteUv(w, PosUVIndices);
        if (!Stippling.HasFlag(Stippling.NoNeg) && SidesType == SidesType.Clockwise) WriteUv(w, NegUVIndices);
    }

    private void WriteUv(DatBinaryWriter w, IReadOnlyList<byte> uv)
    {
        for (var i = 0; i < VertexIds.Count; i++) w.WriteByte(i < uv.Count ? uv[i] : (byte)0);
    }
}
