using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// compiled-scene.json as written, parsed once: the one reader behind <see cref="CompiledScene"/> (the
/// objects and cells as collision queries) and acshadow's view (the same shapes drawn). BSP dumps are named,
/// not read: each use reads them its own way.
/// </summary>
internal sealed record CompiledSceneFile(uint LandblockId, Vector3? WorldOrigin, IReadOnlyList<float> MoverRadii, double TolerancePercent,
    IReadOnlyList<CompiledSceneFile.Placed> Objects, IReadOnlyList<CompiledSceneFile.Cell> Cells)
{
    /// <summary>One placed object: its chosen model (null: none), its shapes in the entity frame, and its bound (null: none).</summary>
    internal sealed record Placed(int Index, uint Id, SceneObjectKind Kind, string? Model, uint? CellId, Vector3 Position, Quaternion Rotation,
        Sphere? Bound, IReadOnlyList<Shape> Shapes);

    /// <summary>One indoor cell; <see cref="File"/> is its BSP dump, null when it has none (and then it has no model read).</summary>
    internal sealed record Cell(uint CellId, string? Model, Vector3 Position, Quaternion Rotation, string? File);

    /// <summary>One shape of a chosen model; <see cref="Source"/> names the part or primitive it came from.</summary>
    internal abstract record Shape(string Type, string? Source);

    internal sealed record SphereShape(string? Source, Vector3 Center, float Radius) : Shape("sphere", Source);

    internal sealed record CylinderShape(string? Source, Vector3 Base, float Radius, float Height) : Shape("cylinder", Source);

    /// <summary>A part's shape, in part space with the part's pose.</summary>
    internal abstract record PartShape(string Type, string? Source, PartPose Pose) : Shape(Type, Source);

    internal sealed record BoxShape(string? Source, PartPose Pose, OrientedBox Box) : PartShape("box", Source, Pose);

    internal sealed record HullShape(string? Source, PartPose Pose, ConvexPolytope Hull) : PartShape("hull", Source, Pose);

    /// <summary>A part answered by its retail BSP, read from <see cref="File"/>; <see cref="GfxObjId"/> as the file gives it (null: not given as a hex id).</summary>
    internal sealed record BspShape(string? Source, PartPose Pose, string File, uint? GfxObjId) : PartShape("bsp", Source, Pose);

    /// <summary>The BSP dumps this scene names: its objects' retail parts, then its cells'.</summary>
    public IEnumerable<string> DumpFiles() =>
        Objects.SelectMany(o => o.Shapes.OfType<BspShape>().Select(b => b.File)).Concat(Cells.Select(c => c.File).OfType<string>());

    public static CompiledSceneFile Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.CompiledScene, "compiled-scene.json");
        var objects = new List<Placed>();
        foreach (var o in Arr(root, "objects"))
        {
            var frame = Prop(o, "landblockFrame");
            var position = Vec(Prop(frame, "origin"));
            var rotation = Rotation(Prop(frame, "orientation"), "an object's landblockFrame orientation");
            var model = Prop(o, "model");
            var shapes = Arr(o, "shapes").Select(ReadShape).ToArray();
            var id = JsonIds.TryParse(Str(o, "id"), out var parsed) ? parsed : throw new FormatException("id is not a hex id");
            var index = Int(o, "index");
            var cellId = o.TryGetProperty("cellId", out var c) && c.ValueKind == JsonValueKind.String
                ? JsonIds.TryParse(c.GetString()!, out var parsedCell) ? parsedCell : throw new FormatException("cellId is not a hex id")
                : (uint?)null;
            var kind = SceneObjectKinds.Parse(Str(o, "kind"));
            var modelName = model.ValueKind == JsonValueKind.Null ? null : model.GetString();
            // The bound is read only where there is something to bound.
            var bound = Prop(o, "bound");
            objects.Add(new Placed(index, id, kind, modelName, cellId, position, rotation,
                shapes.Length == 0 || bound.ValueKind == JsonValueKind.Null ? null : Sphere(bound), shapes));
        }
        var cells = new List<Cell>();
        foreach (var e in root.TryGetProperty("cells", out _) ? Arr(root, "cells") : [])
        {
            var cellId = JsonIds.TryParse(Str(e, "cellId"), out var parsed) ? parsed : throw new FormatException("cellId is not a hex id");
            var frame = Prop(e, "landblockFrame");
            var position = Vec(Prop(frame, "origin"));
            var rotation = Rotation(Prop(frame, "orientation"), "a cell's landblockFrame orientation");
            var file = Prop(e, "file");
            cells.Add(file.ValueKind == JsonValueKind.Null
                ? new Cell(cellId, null, position, rotation, null)
                : new Cell(cellId, Str(e, "model"), position, rotation, file.GetString()!));
        }
        var landblock = JsonIds.TryParse(Str(root, "landblockId"), out var lb) ? lb : throw new FormatException("landblockId is not a hex id");
        var worldOrigin = root.TryGetProperty("worldOrigin", out var w) ? Vec(w) : (Vector3?)null;
        var radii = Arr(root, "moverRadii").Select(Number).ToArray();
        return new CompiledSceneFile(landblock, worldOrigin, radii, Prop(root, "tolerancePercent").GetDouble(), objects, cells);
    }

    private static Shape ReadShape(JsonElement s)
    {
        var type = Str(s, "type");
        var source = s.TryGetProperty("source", out var named) && named.ValueKind == JsonValueKind.String ? named.GetString() : null;
        switch (type)
        {
            case "sphere":
                return new SphereShape(source, Vec(Prop(s, "center")), Float(s, "radius"));
            case "cylinder":
                return new CylinderShape(source, Vec(Prop(s, "base")), Float(s, "radius"), Float(s, "height"));
        }
        var pose = Prop(s, "pose");
        var scale = Float(pose, "scale");
        // A part scaled by 0 or less has no (or an inside-out) shape: no file `scene` writes holds one.
        if (!(float.IsFinite(scale) && scale > 0f))
            throw new FormatException($"a part's pose scale must be a positive number, not {scale.ToString(System.Globalization.CultureInfo.InvariantCulture)}");
        var partPose = new PartPose(Vec(Prop(pose, "position")), Rotation(Prop(pose, "orientation"), "a part's pose orientation"), scale);
        return type switch
        {
            "box" => new BoxShape(source, partPose, new OrientedBox(Vec(Prop(s, "center")), Rotation(Prop(s, "axes"), "a box's axes"), Vec(Prop(s, "halfExtents")))),
            "hull" => new HullShape(source, partPose, Hull(s)),
            "bsp" => new BspShape(source, partPose, Str(s, "file"),
                s.TryGetProperty("gfxObjId", out var g) && g.ValueKind == JsonValueKind.String && JsonIds.TryParse(g.GetString(), out var gfx) ? gfx : null),
            _ => throw new FormatException($"shape type \"{type}\" is not sphere, cylinder, box, hull or bsp"),
        };
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
}
