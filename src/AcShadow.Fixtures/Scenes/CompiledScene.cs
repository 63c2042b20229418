using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Scenes;

/// <summary>
/// compiled-scene.json (what <c>acshadow scene</c> writes) loaded: every object answered by the model the
/// compiler chose for it — spheres, cylinders, part boxes, part convex hulls, or the part's retail BSP
/// read from the dump beside it — and every indoor cell by its retail tree (cells/0x%08X.bsp.json, asked
/// as <see cref="CellOverlapQuery"/> asks it), with the same float operations the tool checked them with.
/// <see cref="Query"/> takes landblock-relative centres.
/// </summary>
public sealed class CompiledScene
{
    public uint LandblockId { get; }
    public IReadOnlyList<float> MoverRadii { get; }
    public double TolerancePercent { get; }
    public IReadOnlyList<CompiledObject> Objects { get; }
    public IReadOnlyList<CompiledCell> Cells { get; }
    public SceneQuery Query { get; }

    private CompiledScene(uint landblockId, IReadOnlyList<float> moverRadii, double tolerance, IReadOnlyList<CompiledObject> objects, IReadOnlyList<CompiledCell> cells, SceneQuery query)
    {
        LandblockId = landblockId;
        MoverRadii = moverRadii;
        TolerancePercent = tolerance;
        Objects = objects;
        Cells = cells;
        Query = query;
    }

    /// <summary>Does a sphere at this landblock-relative centre touch anything of the scene, object or cell?</summary>
    public bool Overlaps(Vector3 landblockCenter, float radius) => Query.Overlaps(landblockCenter, radius);

    /// <summary>The cells whose walls, floors or ceilings a sphere at this landblock-relative centre touches.</summary>
    public IEnumerable<uint> TouchingCells(Vector3 landblockCenter, float radius) => Query.TouchingCells(landblockCenter, radius);

    /// <summary>Loads <c>compiled-scene.json</c> from a folder <c>acshadow scene --out</c> wrote, with the BSP dumps it names.</summary>
    public static CompiledScene Load(string folder)
    {
        var path = Path.Combine(folder, FileFormats.CompiledScene.Path);
        if (!File.Exists(path))
            throw new FileNotFoundException($"{path} is missing; generate it with `acshadow scene --landblock 0xXXYY --out {folder}`", path);
        try
        {
            return Read(File.ReadAllText(path), file => BspFileReader.Read(File.ReadAllText(Path.Combine(folder, file))));
        }
        catch (FormatException e)
        {
            throw new FormatException($"{path}: {e.Message}", e);
        }
        catch (JsonException e)
        {
            throw new FormatException($"{path}: not JSON: {e.Message}", e);
        }
    }

    /// <summary>From the file's text; <paramref name="bspFile"/> reads a BSP dump by its folder-relative path.</summary>
    public static CompiledScene Read(string json, Func<string, BspDump> bspFile)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.CompiledScene, "compiled-scene.json");
        var trees = new Dictionary<string, ISphereOverlap>(StringComparer.Ordinal);
        var objects = new List<CompiledObject>();
        var queries = new List<PlacedQuery>();
        foreach (var o in Arr(root, "objects"))
        {
            var frame = Prop(o, "landblockFrame");
            var position = Vec(Prop(frame, "origin"));
            var rotation = Quat(Prop(frame, "orientation"));
            var model = Prop(o, "model");
            var shapes = Arr(o, "shapes").Select(s => Shape(s, trees, bspFile)).ToArray();
            var id = JsonIds.TryParse(Str(o, "id"), out var parsed) ? parsed : throw new FormatException("id is not a hex id");
            var index = Int(o, "index");
            var cellId = o.TryGetProperty("cellId", out var c) && c.ValueKind == JsonValueKind.String
                ? JsonIds.TryParse(c.GetString()!, out var parsedCell) ? parsedCell : throw new FormatException("cellId is not a hex id")
                : (uint?)null;
            objects.Add(new CompiledObject(index, id, SceneObjectKinds.Parse(Str(o, "kind")), model.ValueKind == JsonValueKind.Null ? null : model.GetString(), shapes.Length, position, rotation) { CellId = cellId });
            var bound = Prop(o, "bound");
            if (shapes.Length == 0 || bound.ValueKind == JsonValueKind.Null) continue;
            queries.Add(new PlacedQuery(index, id, position, rotation, new AnyOverlap(shapes),
                Vec(Prop(bound, "center")), Float(bound, "radius")));
        }
        var cells = new List<CompiledCell>();
        var cellQueries = new List<SceneCell>();
        foreach (var e in root.TryGetProperty("cells", out _) ? Arr(root, "cells") : [])
        {
            var cellId = JsonIds.TryParse(Str(e, "cellId"), out var parsed) ? parsed : throw new FormatException("cellId is not a hex id");
            var frame = Prop(e, "landblockFrame");
            var position = Vec(Prop(frame, "origin"));
            var rotation = Quat(Prop(frame, "orientation"));
            var file = Prop(e, "file");
            if (file.ValueKind == JsonValueKind.Null) continue;
            cells.Add(new CompiledCell(cellId, Str(e, "model"), position, rotation));
            try
            {
                cellQueries.Add(new SceneCell(cellId, new CellOverlapQuery(bspFile(file.GetString()!), position, rotation)));
            }
            catch (ArgumentException ex)
            {
                throw new FormatException($"cell {JsonIds.Format(cellId)}: {ex.Message}", ex);
            }
        }
        var landblock = JsonIds.TryParse(Str(root, "landblockId"), out var lb) ? lb : throw new FormatException("landblockId is not a hex id");
        var radii = Arr(root, "moverRadii").Select(Number).ToArray();
        return new CompiledScene(landblock, radii, Prop(root, "tolerancePercent").GetDouble(), objects, cells, new SceneQuery(queries, cellQueries));
    }

    private static ISphereOverlap Shape(JsonElement s, Dictionary<string, ISphereOverlap> trees, Func<string, BspDump> bspFile)
    {
        var type = Str(s, "type");
        switch (type)
        {
            case "sphere":
                var center = Vec(Prop(s, "center"));
                var r = Float(s, "radius");
                return new SphereShape(center, r);
            case "cylinder":
                return new CylinderShape(Vec(Prop(s, "base")), Float(s, "radius"), Float(s, "height"));
        }
        var pose = Prop(s, "pose");
        var partPose = new PartPose(Vec(Prop(pose, "position")), Quat(Prop(pose, "orientation")), Float(pose, "scale"));
        ISphereOverlap part = type switch
        {
            "box" => new BoxSphereQuery(new OrientedBox(Vec(Prop(s, "center")), Quat(Prop(s, "axes")),
                Vec(Prop(s, "halfExtents")))),
            "hull" => Hull(s),
            "bsp" => Tree(Str(s, "file"), trees, bspFile),
            _ => throw new FormatException($"shape type \"{type}\" is not sphere, cylinder, box, hull or bsp"),
        };
        return new PosedQuery(partPose, part);
    }

    private static ConvexPolytope Hull(JsonElement s)
    {
        var vertices = Arr(s, "vertices").Select(Vec).ToArray();
        var faces = Arr(s, "faces").Select((f, i) =>
        {
            var corners = Arr(f, "vertices").Select(e => e.GetInt32()).ToArray();
            if (corners.Length < 3 || corners.Any(c => c < 0 || c >= vertices.Length)) throw new FormatException($"hull face {i}: vertex indices must name at least 3 of the hull's vertices");
            return new CompiledPolygon(i, new Plane(Vec(Prop(f, "normal")), Float(f, "d")), corners.Select(c => vertices[c]).ToArray());
        }).ToArray();
        return new ConvexPolytope(vertices, faces);
    }

    private static ISphereOverlap Tree(string file, Dictionary<string, ISphereOverlap> trees, Func<string, BspDump> bspFile)
    {
        if (!trees.TryGetValue(file, out var query))
            trees[file] = query = new BspSphereQuery(CompiledBsp.Compile(bspFile(file)));
        return query;
    }

    private sealed class SphereShape(Vector3 center, float radius) : ISphereOverlap
    {
        public bool Overlaps(Vector3 c, float r) => SphereBounds.IsValidProbe(c, r) && SphereSphereTest.Touches(center, radius, c, r);
    }

    private sealed class CylinderShape(Vector3 baseCenter, float radius, float height) : ISphereOverlap
    {
        public bool Overlaps(Vector3 c, float r) => SphereBounds.IsValidProbe(c, r) && CylinderSphereTest.Touches(baseCenter, radius, height, c, r);
    }
}
