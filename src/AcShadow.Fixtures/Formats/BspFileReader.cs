using System.Text.Json;
using AcShadow.Fixtures.Bsp;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// Reads an "acshadow.bsp/1" file back into a <see cref="BspDump"/>, so consumers of the fixtures query
/// exactly what the tool computed. Malformed input is a <see cref="FormatException"/> naming the field.
/// </summary>
internal static class BspFileReader
{
    public static BspDump Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Bsp, "BSP file");
        if (!Json.JsonIds.TryParse(Str(root, "gfxObjId"), out var id)) throw new FormatException("gfxObjId is not a hex id");
        return ReadBody(root, id, Arr(root, "diagnostics").Select(e => e.GetString() ?? "").ToArray());
    }

    /// <summary>
    /// The tree part of a BSP file (boundingSphere, vertices, polygons, nodes, stats), wherever it sits: a
    /// cell file carries its PhysicsBSP in this shape too.
    /// </summary>
    internal static BspDump ReadBody(JsonElement root, uint id, IReadOnlyList<string> diagnostics)
    {
        var vertices = Arr(root, "vertices").Select(v => new BspVertex(Int(v, "id"), Vec(Prop(v, "position")))).ToArray();
        var polygons = Arr(root, "polygons").Select(p => new BspPolygon(
            Int(p, "id"),
            Arr(p, "vertexIds").Select(e => e.GetInt32()).ToArray(),
            OptionalPlane(Prop(p, "plane")),
            (SidesType)Int(p, "sidesType"),
            (Stippling)Int(p, "stippling"))).ToArray();
        var nodes = Arr(root, "nodes").Select(ReadNode).ToArray();
        var s = Prop(root, "stats");
        var stats = new BspStats(Int(s, "vertexCount"), Int(s, "polygonCount"), Int(s, "nodeCount"), Int(s, "leafCount"),
            Int(s, "solidLeafCount"), Int(s, "maxDepth"),
            Arr(s, "degeneratePolygons").Select(e => e.GetInt32()).ToArray(),
            Arr(s, "nonPlanarPolygons").Select(e => e.GetInt32()).ToArray());
        return new BspDump(id, Sphere(Prop(root, "boundingSphere")), vertices, polygons, nodes, stats, diagnostics);
    }

    private static BspNode ReadNode(JsonElement n)
    {
        var tag = Str(n, "type");
        var type = ParseTag(tag);
        if (type == BspNodeType.Leaf)
            return new BspNode(Int(n, "index"), type, null, Sphere(Prop(n, "sphere")), null, null,
                Int(n, "leafIndex"), Prop(n, "solid").GetBoolean(), Arr(n, "polygons").Select(e => e.GetInt32()).ToArray());
        return new BspNode(Int(n, "index"), type, OptionalPlane(Prop(n, "plane")), Sphere(Prop(n, "sphere")),
            OptionalInt(Prop(n, "pos")), OptionalInt(Prop(n, "neg")), 0, false, []);
    }

    private static BspNodeType ParseTag(string tag)
    {
        if (tag.Length != 4) throw new FormatException($"node type \"{tag}\" is not a 4-letter tag");
        var value = ((uint)tag[0] << 24) | ((uint)tag[1] << 16) | ((uint)tag[2] << 8) | tag[3];
        var type = (BspNodeType)value;
        if (!Enum.IsDefined(type)) throw new FormatException($"unknown node type \"{tag}\"");
        return type;
    }

    private static int? OptionalInt(JsonElement e) => e.ValueKind == JsonValueKind.Null ? null : e.GetInt32();
}
