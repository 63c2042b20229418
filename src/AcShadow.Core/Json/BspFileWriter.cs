using AcShadow.Core.Bsp;
using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Json;

/// <summary>Writes a <see cref="BspDump"/> as the canonical "acshadow.bsp/1" file (docs/formats.md).</summary>
public static class BspFileWriter
{
    public static byte[] Write(BspDump dump) => CanonicalJsonWriter.WriteUtf8(ToJson(dump));

    public static JsonObj ToJson(BspDump dump)
    {
        var root = new JsonObj()
            .Add("format", BspFileFormat.Format)
            .Add("gfxObjId", JsonIds.Format(dump.GfxObjId))
            .Add("boundingSphere", JsonShapes.Sphere(dump.BoundingSphere))
            .Add("vertices", JsonArr.Of(dump.Vertices, v => new JsonObj().Add("id", v.Id).Add("position", v.Position)))
            .Add("polygons", JsonArr.Of(dump.Polygons, Polygon))
            .Add("nodes", JsonArr.Of(dump.Nodes, Node))
            .Add("stats", Stats(dump.Stats))
            .Add("diagnostics", JsonArr.Of(dump.Diagnostics));
        return root;
    }

    private static JsonNode Polygon(BspPolygon p) => new JsonObj()
        .Add("id", p.Id)
        .Add("vertexIds", JsonArr.Of(p.VertexIds))
        .Add("plane", p.Plane is { } plane ? JsonShapes.Plane(plane) : JsonNull.Value)
        .Add("sidesType", (int)p.SidesType)
        .Add("stippling", (int)p.Stippling);

    private static JsonNode Node(BspNode n)
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
