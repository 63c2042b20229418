using System.Numerics;
using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Json;

/// <summary>
/// Writes a <see cref="BspDump"/> as the canonical "acshadow.bsp/1" file (docs/formats.md).
/// <see cref="Write"/> streams the bytes directly (BSP dumps are most of a batch's output, and building the
/// tree first cost more than everything else together); <see cref="ToJson"/> is the same file as a
/// <see cref="JsonNode"/> tree, and a test holds the two to the same bytes.
/// </summary>
public static class BspFileWriter
{
    public static byte[] Write(BspDump dump)
    {
        var t = new Utf8JsonText(256 + dump.Polygons.Count * 160 + dump.Nodes.Count * 200 + dump.Vertices.Count * 60);
        t.Raw("{\n  \"format\": ").String(BspFileFormat.Format)
            .Raw(",\n  \"gfxObjId\": ").String(JsonIds.Format(dump.GfxObjId))
            .Raw(",\n  \"boundingSphere\": ");
        WriteSphere(t, dump.BoundingSphere);
        t.Raw(",\n  \"vertices\": ");
        Items(t, dump.Vertices, v => t.Raw("{\"id\": ").Int(v.Id).Raw(", \"position\": ").Vector(v.Position).Raw("}"));
        t.Raw(",\n  \"polygons\": ");
        Items(t, dump.Polygons, p => Polygon(t, p));
        t.Raw(",\n  \"nodes\": ");
        Items(t, dump.Nodes, n => Node(t, n));
        var s = dump.Stats;
        t.Raw(",\n  \"stats\": {\n    \"vertexCount\": ").Int(s.VertexCount)
            .Raw(",\n    \"polygonCount\": ").Int(s.PolygonCount)
            .Raw(",\n    \"nodeCount\": ").Int(s.NodeCount)
            .Raw(",\n    \"leafCount\": ").Int(s.LeafCount)
            .Raw(",\n    \"solidLeafCount\": ").Int(s.SolidLeafCount)
            .Raw(",\n    \"maxDepth\": ").Int(s.MaxDepth)
            .Raw(",\n    \"degeneratePolygons\": ").IntArray(s.DegeneratePolygons)
            .Raw(",\n    \"nonPlanarPolygons\": ").IntArray(s.NonPlanarPolygons)
            .Raw("\n  },\n  \"diagnostics\": [");
        for (var i = 0; i < dump.Diagnostics.Count; i++)
        {
            if (i > 0) t.Raw(", ");
            t.String(dump.Diagnostics[i]);
        }
        return t.Raw("]\n}\n").ToArray();
    }

    /// <summary>An array of objects: one a line at depth 2, or [] when empty (the canonical layout).</summary>
    private static void Items<T>(Utf8JsonText t, IReadOnlyList<T> items, Action<T> item)
    {
        if (items.Count == 0) { t.Raw("[]"); return; }
        t.Raw("[\n");
        for (var i = 0; i < items.Count; i++)
        {
            t.Indent(2);
            item(items[i]);
            t.Raw(i < items.Count - 1 ? ",\n" : "\n");
        }
        t.Raw("  ]");
    }

    private static void WriteSphere(Utf8JsonText t, Sphere s) => t.Raw("{\"center\": ").Vector(s.Center).Raw(", \"radius\": ").Float(s.Radius).Raw("}");

    private static void WritePlane(Utf8JsonText t, Plane? plane)
    {
        if (plane is { } p) t.Raw("{\"normal\": ").Vector(p.Normal).Raw(", \"d\": ").Float(p.D).Raw("}");
        else t.Raw("null");
    }

    /// <summary>
    /// On one line only when the canonical writer would inline it: no plane object (degenerate) and at
    /// most four vertex ids; otherwise one member a line.
    /// </summary>
    private static void Polygon(Utf8JsonText t, BspPolygon p)
    {
        if (p.Plane is null && p.VertexIds.Count <= 4)
        {
            t.Raw("{\"id\": ").Int(p.Id).Raw(", \"vertexIds\": ").IntArray(p.VertexIds).Raw(", \"plane\": null, \"sidesType\": ")
                .Int((int)p.SidesType).Raw(", \"stippling\": ").Int((int)p.Stippling).Raw("}");
            return;
        }
        t.Raw("{\n      \"id\": ").Int(p.Id).Raw(",\n      \"vertexIds\": ").IntArray(p.VertexIds).Raw(",\n      \"plane\": ");
        WritePlane(t, p.Plane);
        t.Raw(",\n      \"sidesType\": ").Int((int)p.SidesType).Raw(",\n      \"stippling\": ").Int((int)p.Stippling).Raw("\n    }");
    }

    private static void Node(Utf8JsonText t, BspNode n)
    {
        t.Raw("{\n      \"index\": ").Int(n.Index).Raw(",\n      \"type\": ").String(n.Type.Tag());
        if (n.IsLeaf)
        {
            t.Raw(",\n      \"sphere\": ");
            WriteSphere(t, n.Sphere);
            t.Raw(",\n      \"leafIndex\": ").Int(n.LeafIndex).Raw(",\n      \"solid\": ").Raw(n.Solid ? "true" : "false")
                .Raw(",\n      \"polygons\": ").IntArray(n.PolygonIds).Raw("\n    }");
            return;
        }
        t.Raw(",\n      \"plane\": ");
        WritePlane(t, n.Plane);
        t.Raw(",\n      \"sphere\": ");
        WriteSphere(t, n.Sphere);
        t.Raw(",\n      \"pos\": ");
        if (n.Pos is { } pos) t.Int(pos); else t.Raw("null");
        t.Raw(",\n      \"neg\": ");
        if (n.Neg is { } neg) t.Int(neg); else t.Raw("null");
        t.Raw("\n    }");
    }

    public static JsonObj ToJson(BspDump dump)
    {
        var root = new JsonObj()
            .Add("format", BspFileFormat.Format)
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
