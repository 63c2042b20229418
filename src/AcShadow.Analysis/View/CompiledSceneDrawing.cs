using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcShadow.Analysis.Compile;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// One thing a compiled scene places, drawn by the model chosen for it: a placed object ("#3 Setup
/// 0x020019FF") or an indoor cell ("cell 0xA9B40100", always <see cref="ViewModels.Cells"/>), its id, its
/// landblock-relative frame and its shapes in that frame.
/// </summary>
public sealed record CompiledPlacement(string Name, uint Id, string Model, ViewFrame Frame, IReadOnlyList<ViewShape> Shapes);

/// <summary>
/// compiled-scene.json (what <c>acshadow scene</c> writes) read for drawing: each object's chosen model and
/// its shapes exactly as the file gives them — spheres and cylinders in the entity frame; boxes, hulls and
/// BSP parts in part space with the part's pose — and each indoor cell's retail polygons from its dump.
/// Only what the file names is read: a BSP shape's dump must be the one its GfxObj id names
/// (gfxobjs/0x%08X.bsp.json) and hold that GfxObj, a cell's the cell's (cells/0x%08X.bsp.json); anything
/// else is a <see cref="FormatException"/>, so a file edited by hand or mixed with another scene's dumps is
/// refused rather than drawn wrong. <see cref="Undrawn"/> counts the placed objects the file gives no model
/// (ids that are not a Setup or GfxObj of the dat).
/// </summary>
public sealed record CompiledSceneDrawing(uint LandblockId, Vector3 WorldOrigin, IReadOnlyList<float> MoverRadii, double TolerancePercent,
    IReadOnlyList<CompiledPlacement> Objects, IReadOnlyList<CompiledPlacement> Cells, int Undrawn)
{
    /// <param name="bspFile">Reads a BSP dump by its path relative to compiled-scene.json's folder.</param>
    public static CompiledSceneDrawing Read(string json, Func<string, BspDump> bspFile)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        if (root.ValueKind != JsonValueKind.Object)
            throw new FormatException("not a JSON object");
        var format = root.TryGetProperty("format", out var f) && f.ValueKind == JsonValueKind.String ? f.GetString() : null;
        if (format != FileFormats.CompiledScene.Format)
            throw new FormatException($"its format is {(format is null ? "missing" : $"\"{format}\"")}, not \"{FileFormats.CompiledScene.Format}\" (a file `acshadow scene` writes)");
        var landblock = Id(root, "landblockId");
        var origin = Prop(root, "worldOrigin");
        var worldOrigin = new Vector3(Float(origin[0]), Float(origin[1]), Float(origin[2]));
        var radii = Prop(root, "moverRadii").EnumerateArray().Select(Float).ToArray();

        var objects = new List<CompiledPlacement>();
        var undrawn = 0;
        foreach (var o in Prop(root, "objects").EnumerateArray())
        {
            var index = Prop(o, "index").GetInt32();
            var id = Id(o, "id");
            var kind = Prop(o, "kind").GetString() switch
            {
                "setup" => "Setup",
                "gfxObj" => "GfxObj",
                var other => other ?? throw new FormatException($"object #{index}: \"kind\" is null"),
            };
            var name = $"#{index} {kind} {JsonIds.Format(id)}";
            var model = Prop(o, "model");
            if (model.ValueKind == JsonValueKind.Null)
            {
                undrawn++;
                continue;
            }
            var modelName = model.GetString()!;
            if (!ModelLadder.Names.Contains(modelName))
                throw new FormatException($"object #{index}: model \"{modelName}\" is none of the ladder's ({string.Join(", ", ModelLadder.Names)})");
            var shapes = Prop(o, "shapes").EnumerateArray().Select(s => Shape(s, bspFile)).OfType<ViewShape>().ToArray();
            objects.Add(new CompiledPlacement(name, id, modelName, Frame(o), shapes));
        }

        var cells = new List<CompiledPlacement>();
        foreach (var c in root.TryGetProperty("cells", out var list) ? list.EnumerateArray().ToArray() : [])
        {
            var cellId = Id(c, "cellId");
            var file = Prop(c, "file");
            if (file.ValueKind == JsonValueKind.Null) continue;
            var dump = Dump(bspFile, file.GetString()!, CompiledSceneWriter.CellBspPath(cellId), cellId, $"cell {JsonIds.Format(cellId)}");
            cells.Add(new CompiledPlacement($"cell {JsonIds.Format(cellId)}", cellId, ViewModels.Cells, Frame(c),
                [ShapeTessellation.Polygons($"cell {JsonIds.Format(cellId)} physics polygons", new PartPose(Vector3.Zero, Quaternion.Identity, 1f), dump)]));
        }
        return new CompiledSceneDrawing(landblock, worldOrigin, radii, Prop(root, "tolerancePercent").GetDouble(), objects, cells, undrawn);
    }

    private static ViewShape? Shape(JsonElement s, Func<string, BspDump> bspFile)
    {
        var type = Prop(s, "type").GetString();
        var source = Prop(s, "source").GetString() ?? throw new FormatException("a shape's \"source\" is null");
        var name = type == "bsp" ? source : $"{source} as {type}";
        switch (type)
        {
            case "sphere":
                var r = Float(Prop(s, "radius"));
                return r > 0f ? ShapeTessellation.Sphere(name, Vec(Prop(s, "center")), r) : null;
            case "cylinder":
                var cr = Float(Prop(s, "radius"));
                var height = Float(Prop(s, "height"));
                return cr > 0f && height >= 0f ? ShapeTessellation.Cylinder(name, Vec(Prop(s, "base")), cr, height) : null;
        }
        var poseJson = Prop(s, "pose");
        var pose = new PartPose(Vec(Prop(poseJson, "position")), Quat(Prop(poseJson, "orientation")), Float(Prop(poseJson, "scale")));
        switch (type)
        {
            case "box":
                return ShapeTessellation.Box(name, pose, new OrientedBox(Vec(Prop(s, "center")), Quat(Prop(s, "axes")), Vec(Prop(s, "halfExtents"))));
            case "hull":
                var vertices = Prop(s, "vertices").EnumerateArray().Select(Vec).ToArray();
                var faces = Prop(s, "faces").EnumerateArray().Select((face, i) =>
                {
                    var corners = Prop(face, "vertices").EnumerateArray().Select(e => e.GetInt32()).ToArray();
                    if (corners.Length < 3 || corners.Any(c => c < 0 || c >= vertices.Length))
                        throw new FormatException($"{source}: hull face {i}: vertex indices must name at least 3 of the hull's {vertices.Length} vertices");
                    return new CompiledPolygon(i, new Plane(Vec(Prop(face, "normal")), Float(Prop(face, "d"))), corners.Select(c => vertices[c]).ToArray());
                }).ToArray();
                return ShapeTessellation.Solid(name, pose, new ConvexPolytope(vertices, faces));
            case "bsp":
                var gfxObj = Id(s, "gfxObjId");
                return ShapeTessellation.Polygons(name, pose, Dump(bspFile, Prop(s, "file").GetString()!, FileFormats.Bsp.PathFor(gfxObj), gfxObj, source));
            default:
                throw new FormatException($"{source}: shape type \"{type}\" is not sphere, cylinder, box, hull or bsp");
        }
    }

    /// <summary>The dump a shape or cell names, which must be the file its id names and hold that id's tree.</summary>
    private static BspDump Dump(Func<string, BspDump> bspFile, string file, string expected, uint id, string what)
    {
        if (file != expected)
            throw new FormatException($"{what}: its BSP dump is \"{file}\", not {expected} (the file its id names)");
        var dump = bspFile(file);
        if (dump.GfxObjId != id)
            throw new FormatException($"{what}: {file} holds the tree of {JsonIds.Format(dump.GfxObjId)}, not of {JsonIds.Format(id)}");
        return dump;
    }

    private static JsonElement Prop(JsonElement e, string name) =>
        e.ValueKind == JsonValueKind.Object && e.TryGetProperty(name, out var value) ? value : throw new FormatException($"\"{name}\" is missing");

    private static ViewFrame Frame(JsonElement e)
    {
        var frame = Prop(e, "landblockFrame");
        return new ViewFrame(Vec(Prop(frame, "origin")), Quat(Prop(frame, "orientation")));
    }

    private static uint Id(JsonElement e, string name) =>
        JsonIds.TryParse(Prop(e, name).GetString(), out var id) ? id : throw new FormatException($"\"{name}\" is not a hex id");

    private static Vector3 Vec(JsonElement e) =>
        e.GetArrayLength() == 3 ? new Vector3(Float(e[0]), Float(e[1]), Float(e[2])) : throw new FormatException("a vector has not 3 numbers");

    private static Quaternion Quat(JsonElement e) =>
        new(Float(Prop(e, "x")), Float(Prop(e, "y")), Float(Prop(e, "z")), Float(Prop(e, "w")));

    private static float Float(JsonElement e)
    {
        var value = e.GetSingle();
        return float.IsFinite(value) ? value : throw new FormatException(string.Create(CultureInfo.InvariantCulture, $"{e.GetRawText()} is not a finite float"));
    }
}
