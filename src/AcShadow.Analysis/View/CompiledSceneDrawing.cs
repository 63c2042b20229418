using System.Globalization;
using System.Numerics;
using AcShadow.Analysis.Compile;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;

namespace AcShadow.Analysis.View;

/// <summary>
/// One thing a compiled scene places, drawn by the model chosen for it: a placed object ("#3 Setup
/// 0x020019FF", its scene index 3) or an indoor cell ("cell 0xA9B40100", index −1, always
/// <see cref="ViewModels.Cells"/>), its id, its landblock-relative frame and its shapes in that frame.
/// </summary>
public sealed record CompiledPlacement(int Index, string Name, uint Id, string Model, Frame Frame, IReadOnlyList<ViewShape> Shapes);

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
    /// <summary>What the compile reported for each object ("0x02003000: non-uniform-scale: …"), in file order.</summary>
    public IReadOnlyList<string> Warnings { get; init; } = [];

    /// <summary>
    /// Reads the file once (the fixtures package's reader) and draws it; refused unless the package also loads
    /// it as a <see cref="CompiledScene"/>, so nothing is drawn that a consumer could not query.
    /// </summary>
    /// <param name="bspFile">Reads a BSP dump by its path relative to compiled-scene.json's folder.</param>
    public static CompiledSceneDrawing Read(string json, Func<string, BspDump> bspFile)
    {
        var file = CompiledSceneFile.Read(json);
        var worldOrigin = file.WorldOrigin ?? throw new FormatException("\"worldOrigin\" is missing");
        RequireFinite("worldOrigin", worldOrigin);
        RequireFinite("moverRadii", [.. file.MoverRadii]);
        var objects = new List<CompiledPlacement>();
        var undrawn = 0;
        foreach (var o in file.Objects)
        {
            var kind = o.Kind switch
            {
                SceneObjectKind.Setup => "Setup",
                SceneObjectKind.GfxObj => "GfxObj",
                var other => other.Name(),
            };
            var name = $"#{o.Index} {kind} {JsonIds.Format(o.Id)}";
            if (o.Model is not { } modelName)
            {
                undrawn++;
                continue;
            }
            if (!ModelLadder.Names.Contains(modelName))
                throw new FormatException($"object #{o.Index}: model \"{modelName}\" is none of the ladder's ({string.Join(", ", ModelLadder.Names)})");
            RequireFinite(name, o.Position, o.Rotation);
            var shapes = o.Shapes.Select(s => Shape(s, bspFile)).OfType<ViewShape>().ToArray();
            objects.Add(new CompiledPlacement(o.Index, name, o.Id, modelName, Frame(o.Position, o.Rotation), shapes));
        }

        var cells = new List<CompiledPlacement>();
        foreach (var c in file.Cells)
        {
            if (c.File is null) continue;
            RequireFinite($"cell {JsonIds.Format(c.CellId)}", c.Position, c.Rotation);
            var dump = Dump(bspFile, c.File, CompiledSceneWriter.CellBspPath(c.CellId), c.CellId, $"cell {JsonIds.Format(c.CellId)}");
            cells.Add(new CompiledPlacement(-1, $"cell {JsonIds.Format(c.CellId)}", c.CellId, ViewModels.Cells, Frame(c.Position, c.Rotation),
                [ShapeTessellation.Polygons("physics polygons", new PartPose(Vector3.Zero, Quaternion.Identity, 1f), dump)]));
        }
        CompiledScene.From(file, bspFile);
        return new CompiledSceneDrawing(file.LandblockId, worldOrigin, file.MoverRadii, file.TolerancePercent, objects, cells, undrawn) { Warnings = Diagnostics(json) };
    }

    /// <summary>Each object's and cell's "diagnostics" as warning lines; a file without them has none.</summary>
    private static string[] Diagnostics(string json)
    {
        using var doc = System.Text.Json.JsonDocument.Parse(json);
        var lines = new List<string>();
        foreach (var (array, idName) in new[] { ("objects", "id"), ("cells", "cellId") })
        {
            if (!doc.RootElement.TryGetProperty(array, out var items) || items.ValueKind != System.Text.Json.JsonValueKind.Array) continue;
            foreach (var item in items.EnumerateArray())
            {
                if (!item.TryGetProperty("diagnostics", out var list) || list.ValueKind != System.Text.Json.JsonValueKind.Array) continue;
                var id = item.TryGetProperty(idName, out var v) && v.ValueKind == System.Text.Json.JsonValueKind.String ? v.GetString() : "?";
                foreach (var d in list.EnumerateArray())
                    if (d.ValueKind == System.Text.Json.JsonValueKind.Object && d.TryGetProperty("code", out var code) && d.TryGetProperty("message", out var message))
                        lines.Add($"{id}: {code}: {message}");
            }
        }
        return [.. lines];
    }

    private static ViewShape? Shape(CompiledSceneFile.Shape shape, Func<string, BspDump> bspFile)
    {
        var source = shape.Source ?? throw new FormatException("a shape's \"source\" is missing or null");
        var name = shape.Type == "bsp" ? source : $"{source} as {shape.Type}";
        RequireFinite(source, shape);
        switch (shape)
        {
            case CompiledSceneFile.SphereShape s:
                return s.Radius > 0f ? ShapeTessellation.Sphere(name, s.Center, s.Radius) : null;
            case CompiledSceneFile.CylinderShape c:
                return c.Radius > 0f && c.Height >= 0f ? ShapeTessellation.Cylinder(name, c.Base, c.Radius, c.Height) : null;
            case CompiledSceneFile.BoxShape b:
                return ShapeTessellation.Box(name, b.Pose, b.Box);
            case CompiledSceneFile.HullShape h:
                return ShapeTessellation.Solid(name, h.Pose, h.Hull);
            case CompiledSceneFile.BspShape t:
                var gfxObj = t.GfxObjId ?? throw new FormatException($"{source}: \"gfxObjId\" is missing or not a hex id");
                return ShapeTessellation.Polygons(name, t.Pose, Dump(bspFile, t.File, FileFormats.Bsp.PathFor(gfxObj), gfxObj, source));
            default:
                throw new FormatException($"{source}: shape type \"{shape.Type}\" is not sphere, cylinder, box, hull or bsp");
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

    private static Frame Frame(Vector3 position, Quaternion rotation) => new(position, rotation);

    /// <summary>Every number a drawing uses must be finite: a damaged file is refused rather than drawn as NaN geometry.</summary>
    private static void RequireFinite(string what, params ReadOnlySpan<float> values)
    {
        foreach (var value in values)
            if (!float.IsFinite(value))
                throw new FormatException(string.Create(CultureInfo.InvariantCulture, $"{what}: {value} is not a finite float"));
    }

    private static void RequireFinite(string what, Vector3 v) => RequireFinite(what, v.X, v.Y, v.Z);

    private static void RequireFinite(string what, Quaternion q) => RequireFinite(what, q.X, q.Y, q.Z, q.W);

    private static void RequireFinite(string what, Vector3 position, Quaternion rotation)
    {
        RequireFinite(what, position);
        RequireFinite(what, rotation);
    }

    private static void RequireFinite(string what, CompiledSceneFile.Shape shape)
    {
        if (shape is CompiledSceneFile.PartShape part)
        {
            RequireFinite(what, part.Pose.Position, part.Pose.Rotation);
            RequireFinite(what, part.Pose.Scale);
        }
        switch (shape)
        {
            case CompiledSceneFile.SphereShape s:
                RequireFinite(what, s.Center);
                RequireFinite(what, s.Radius);
                break;
            case CompiledSceneFile.CylinderShape c:
                RequireFinite(what, c.Base);
                RequireFinite(what, c.Radius, c.Height);
                break;
            case CompiledSceneFile.BoxShape b:
                RequireFinite(what, b.Box.Center, b.Box.Axes);
                RequireFinite(what, b.Box.HalfExtents);
                break;
            case CompiledSceneFile.HullShape h:
                foreach (var v in h.Hull.Vertices) RequireFinite(what, v);
                foreach (var f in h.Hull.Faces) RequireFinite(what, f.Normal.X, f.Normal.Y, f.Normal.Z, f.D);
                break;
        }
    }
}
