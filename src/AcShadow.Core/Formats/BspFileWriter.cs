using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;

namespace AcShadow.Core.Formats;

/// <summary>
/// Writes a <see cref="BspDump"/> as the canonical "acshadow.bsp/1" file (docs/formats.md).
/// <see cref="Write"/> streams the bytes directly (BSP dumps are most of a batch's output, and building the
/// tree first cost more than everything else together); <see cref="ToJson"/> is the same file as a
/// <see cref="JsonNode"/> tree, and a test holds the two to the same bytes.
/// </summary>
public static class BspFileWriter
{
    public static byte[] Write(BspDump dump) => Utf8JsonText.Build(dump, Layout);

    /// <summary>The same bytes, lent to <paramref name="use"/> only while it runs (<see cref="Utf8JsonText.Lend"/>).</summary>
    public static TResult Lend<TResult>(BspDump dump, Func<ReadOnlyMemory<byte>, TResult> use) => Utf8JsonText.Lend(dump, Layout, use);

    private static void Layout(Utf8JsonText t, BspDump dump)
    {
        t.Raw("{\n  \"format\": "u8).String(FileFormats.Bsp.Format)
            .Raw(",\n  \"gfxObjId\": "u8).String(JsonIds.Format(dump.GfxObjId))
            .Raw(",\n  \"boundingSphere\": "u8);
        WriteSphere(t, dump.BoundingSphere);
        t.Raw(",\n  \"vertices\": "u8);
        Items(t, dump.Vertices, static (t, v) => t.Raw("{\"id\": "u8).Int(v.Id).Raw(", \"position\": "u8).Vector(v.Position).Raw("}"u8));
        t.Raw(",\n  \"polygons\": "u8);
        Items(t, dump.Polygons, Polygon);
        t.Raw(",\n  \"nodes\": "u8);
        Items(t, dump.Nodes, Node);
        var s = dump.Stats;
        t.Raw(",\n  \"stats\": {\n    \"vertexCount\": "u8).Int(s.VertexCount)
            .Raw(",\n    \"polygonCount\": "u8).Int(s.PolygonCount)
            .Raw(",\n    \"nodeCount\": "u8).Int(s.NodeCount)
            .Raw(",\n    \"leafCount\": "u8).Int(s.LeafCount)
            .Raw(",\n    \"solidLeafCount\": "u8).Int(s.SolidLeafCount)
            .Raw(",\n    \"maxDepth\": "u8).Int(s.MaxDepth)
            .Raw(",\n    \"degeneratePolygons\": "u8).IntArray(s.DegeneratePolygons)
            .Raw(",\n    \"nonPlanarPolygons\": "u8).IntArray(s.NonPlanarPolygons)
            .Raw("\n  },\n  \"diagnostics\": ["u8);
        for (var i = 0; i < dump.Diagnostics.Count; i++)
        {
            if (i > 0) t.Raw(", "u8);
            t.String(dump.Diagnostics[i]);
        }
        t.Raw("]\n}\n"u8);
    }

    /// <summary>An array of objects: one a line at depth 2, or [] when empty (the canonical layout).</summary>
    private static void Items<T>(Utf8JsonText t, IReadOnlyList<T> items, Action<Utf8JsonText, T> item)
    {
        if (items.Count == 0) { t.Raw("[]"u8); return; }
        t.Raw("[\n"u8);
        for (var i = 0; i < items.Count; i++)
        {
            t.Indent(2);
            item(t, items[i]);
            t.Raw(i < items.Count - 1 ? ",\n"u8 : "\n"u8);
        }
        t.Raw("  ]"u8);
    }

    private static void WriteSphere(Utf8JsonText t, Sphere s) => t.Raw("{\"center\": "u8).Vector(s.Center).Raw(", \"radius\": "u8).Float(s.Radius).Raw("}"u8);

    private static void WritePlane(Utf8JsonText t, Plane? plane)
    {
        if (plane is { } p) t.Raw("{\"normal\": "u8).Vector(p.Normal).Raw(", \"d\": "u8).Float(p.D).Raw("}"u8);
        else t.Raw("null"u8);
    }

    /// <summary>
    /// On one line only when the canonical writer would inline it: no plane object (degenerate) and at
    /// most four vertex ids; otherwise one member a line.
    /// </summary>
    private static void Polygon(Utf8JsonText t, BspPolygon p)
    {
        if (p.Plane is null && p.VertexIds.Count <= 4)
        {
            t.Raw("{\"id\": "u8).Int(p.Id).Raw(", \"vertexIds\": "u8).IntArray(p.VertexIds).Raw(", \"plane\": null, \"sidesType\": "u8)
                .Int((int)p.SidesType).Raw(", \"stippling\": "u8).Int((int)p.Stippling).Raw("}"u8);
            return;
        }
        t.Raw("{\n      \"id\": "u8).Int(p.Id).Raw(",\n      \"vertexIds\": "u8).IntArray(p.VertexIds).Raw(",\n      \"plane\": "u8);
        WritePlane(t, p.Plane);
        t.Raw(",\n      \"sidesType\": "u8).Int((int)p.SidesType).Raw(",\n      \"stippling\": "u8).Int((int)p.Stippling).Raw("\n    }"u8);
    }

    private static void Node(Utf8JsonText t, BspNode n)
    {
        t.Raw("{\n      \"index\": "u8).Int(n.Index).Raw(",\n      \"type\": "u8).String(n.Type.Tag(stackalloc char[4]));
        if (n.IsLeaf)
        {
            t.Raw(",\n      \"sphere\": "u8);
            WriteSphere(t, n.Sphere);
            t.Raw(",\n      \"leafIndex\": "u8).Int(n.LeafIndex).Raw(",\n      \"solid\": "u8).Raw(n.Solid ? "true"u8 : "false"u8)
                .Raw(",\n      \"polygons\": "u8).IntArray(n.PolygonIds).Raw("\n    }"u8);
            return;
        }
        t.Raw(",\n      \"plane\": "u8);
        WritePlane(t, n.Plane);
        t.Raw(",\n      \"sphere\": "u8);
        WriteSphere(t, n.Sphere);
        t.Raw(",\n      \"pos\": "u8);
        if (n.Pos is { } pos) t.Int(pos); else t.Raw("null"u8);
        t.Raw(",\n      \"neg\": "u8);
        if (n.Neg is { } neg) t.Int(neg); else t.Raw("null"u8);
        t.Raw("\n    }"u8);
    }

    public static JsonObj ToJson(BspDump dump)
    {
        var root = new JsonObj()
            .Add("format", FileFormats.Bsp.Format)
            .Add("gfxObjId", JsonIds.Format(dump.GfxObjId))
            .Add("boundingSphere", JsonShapes.Sphere(dump.BoundingSphere))
            .Add("vertices", JsonArr.Of(dump.Vertices, v => new JsonObj().Add("id", v.Id).Add("position", v.Position)))
            .Add("polygons", JsonArr.Of(dump.Polygons, PolygonJson))
            .Add("nodes", JsonArr.Of(dump.Nodes, NodeJson))
            .Add("stats", Stats(dump.Stats))
            .Add("diagnostics", JsonArr.Of(dump.Diagnostics));
        return root;
    }

    private static JsonNode PolygonJson(BspPolygon p) => new JsonObj()
        .Add("id", p.Id)
        .Add("vertexIds", JsonArr.Of(p.VertexIds))
        .Add("plane", p.Plane is { } plane ? JsonShapes.Plane(plane) : JsonNull.Value)
        .Add("sidesType", (int)p.SidesType)
        .Add("stippling", (int)p.Stippling);

    private static JsonNode NodeJson(BspNode n)
    {
        var obj = new JsonObj().Add("index", n.Index).Add("type", n.Type.Tag());
        if (n.IsLeaf)
        {
            return obj.Add("sphere", JsonShapes.Sphere(n.Sphere))
                .Add("leafIndex", n.LeafIndex)
                .Add("solid", n.Solid)
                .Add("polygons", JsonArr.Of(n.PolygonIds));
        }
        return obj.Add("plane", n.Plane is { } plane ? JsonShapes.Plane(plane) : JsonNull.Value)
            .Add("sphere", JsonShapes.Sphere(n.Sphere))
            .Add("pos", n.Pos is { } pos ? JsonNum.Of(pos) : JsonNull.Value)
            .Add("neg", n.Neg is { } neg ? JsonNum.Of(neg) : JsonNull.Value);
    }

    private static JsonObj Stats(BspStats s) => new JsonObj()
        .Add("vertexCount", s.VertexCount)
        .Add("polygonCount", s.PolygonCount)
        .Add("nodeCount", s.NodeCount)
        .Add("leafCount", s.LeafCount)
        .Add("solidLeafCount", s.SolidLeafCount)
        .Add("maxDepth", s.MaxDepth)
        .Add("degeneratePolygons", JsonArr.Of(s.DegeneratePolygons))
        .Add("nonPlanarPolygons", JsonArr.Of(s.NonPlanarPolygons));
}
