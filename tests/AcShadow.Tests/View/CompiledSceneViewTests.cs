using System.Globalization;
using System.Numerics;
using AcShadow.Analysis.Compile;
using AcShadow.Analysis.View;
using AcShadow.Core.Bsp;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Bsp;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Tests.Chart;
using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Scenes;
using AcShadow.Tests.Support;
using SharpGLTF.Schema2;

namespace AcShadow.Tests.View;

/// <summary>
/// `view --scene DIR` on a compiled scene: each object in the group of the model `scene` chose for it, in
/// its landblock frame under the world origin, with the triangles and bounds the compiled file gives (a
/// box's 12, a hull's faces, a BSP part's polygons, a cell's walls); the svg rasterises with each solid
/// where the file puts it; the same folder gives the same bytes; a bad or mismatched file is one line.
/// </summary>
public sealed class CompiledSceneViewTests
{
    private const uint Leaf = 0x010044B5, Post = 0x010044B6;

    /// <summary>
    /// A compiled scene written by hand, one object per kind of shape, near each other in landblock 0x1234
    /// (world origin 0x12 × 192, 0x34 × 192): a sphere, a cylinder, a box (turned 90° about z, scaled 2 by its
    /// part's pose, moved 1 m along x), a tetrahedron hull (scaled 2), the sample door's leaf as a BSP part, and
    /// a placed id with no model.
    /// </summary>
    private static string HandBuilt(string leafFile = "gfxobjs/0x010044B5.bsp.json", string boxModel = "part-boxes") => $$"""
        {
          "format": "acshadow.compiled-scene/1",
          "landblockId": "0x1234FFFE",
          "worldOrigin": [3456, 9984, 0],
          "moverRadii": [0.5],
          "tolerancePercent": 0,
          "objects": [
            {{Object(0, "0x02000001", "setup", "spheres", 2, """{"type": "sphere", "source": "Sphere 0", "center": [0, 0, 0.5], "radius": 0.5}""")}},
            {{Object(1, "0x02000002", "setup", "fallback-cylinder", 4, """{"type": "cylinder", "source": "Sphere 0", "base": [0, 0, 0], "radius": 0.3, "height": 1.8}""")}},
            {{Object(2, "0x01000003", "gfxObj", boxModel, 6, $$"""{"type": "box", "source": "part 0 (GfxObj 0x01000003)", "part": 0, "gfxObjId": "0x01000003", {{Pose("[1, 0, 0]", 2)}}, "center": [0, 0, 0.5], "axes": {"w": 0.70710677, "x": 0, "y": 0, "z": 0.70710677}, "halfExtents": [0.5, 0.25, 0.5]}""")}},
            {{Object(3, "0x01000004", "gfxObj", "part-hulls", 10, $$"""{"type": "hull", "source": "part 0 (GfxObj 0x01000004)", "part": 0, "gfxObjId": "0x01000004", {{Pose("[0, 0, 0]", 2)}}, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "faces": [{"vertices": [0, 2, 1], "normal": [0, 0, -1], "d": 0}, {"vertices": [0, 1, 3], "normal": [0, -1, 0], "d": 0}, {"vertices": [0, 3, 2], "normal": [-1, 0, 0], "d": 0}, {"vertices": [1, 2, 3], "normal": [0.57735026, 0.57735026, 0.57735026], "d": -0.57735026}]}""")}},
            {{Object(4, "0x020019FF", "setup", "retail", 16, $$"""{"type": "bsp", "source": "part 0 (GfxObj 0x010044B5)", "part": 0, "gfxObjId": "0x010044B5", {{Pose("[0, 0, 0]", 1)}}, "file": "{{leafFile}}"}""")}},
            { "index": 5, "id": "0x0F000001", "kind": "other", "model": null, "shapes": [], "bound": null,
              "landblockFrame": { "origin": [20, 2, 0], "orientation": { "w": 1, "x": 0, "y": 0, "z": 0 } } }
          ],
          "cells": []
        }
        """;

    private static string Object(int index, string id, string kind, string model, float x, string shape) =>
        string.Create(CultureInfo.InvariantCulture, $$"""
            { "index": {{index}}, "id": "{{id}}", "kind": "{{kind}}", "model": "{{model}}", "shapes": [{{shape}}],
              "landblockFrame": { "origin": [{{x}}, 2, 0], "orientation": { "w": 1, "x": 0, "y": 0, "z": 0 } },
              "bound": { "center": [0, 0, 1], "radius": 3 } }
            """);

    private static string Pose(string position, float scale) =>
        string.Create(CultureInfo.InvariantCulture, $$"""
            "pose": { "position": {{position}}, "orientation": { "w": 1, "x": 0, "y": 0, "z": 0 }, "scale": {{scale}} }
            """);

    /// <summary>A scene folder holding <paramref name="json"/> and the committed dumps of the door's leaf and post.</summary>
    private static TempDir SceneFolder(string json)
    {
        var dir = new TempDir();
        Directory.CreateDirectory(Path.Combine(dir.Path, "gfxobjs"));
        foreach (var id in new[] { Leaf, Post })
            File.Copy(Path.Combine(CommittedFixturesTests.RepositoryFixtures(), FileFormats.Bsp.PathFor(id)), Path.Combine(dir.Path, FileFormats.Bsp.PathFor(id)));
        File.WriteAllText(Path.Combine(dir.Path, FileFormats.CompiledScene.Path), json);
        return dir;
    }

    /// <summary>The sample landblock compiled with the default options (shared with the scene tests), written as `scene --out` writes it.</summary>
    /// <summary>The sample landblock compiled on probes alone (its column a hull), or, <paramref name="walked"/>, as `acshadow scene` compiles it: walked as well (every object retail).</summary>
    private static TempDir CompiledSample(bool walked = false)
    {
        var dir = new TempDir();
        foreach (var file in CompiledSceneFiles.Render((walked ? SceneMovementTests.Walked : SceneCompileTests.Exact).Value, id => SampleChart.Subjects.Value.GfxObj(id) is { } g ? BspExtractor.Extract(g) : null))
        {
            var path = Path.Combine(dir.Path, file.RelativePath);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllBytes(path, file.Content.Span);
        }
        return dir;
    }

    private static string View(TempDir output, params string[] args)
    {
        var run = CliRun.Of(["view", .. args, "--out", output.Path]);
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Error}");
        GltfValidator.AssertValid(output.Path);
        return run.Out;
    }

    /// <summary>A shape node's positions in the landblock's frame (its object's frame applied, not the world origin), glTF axes.</summary>
    private static (Vector3 Min, Vector3 Max) LandblockBounds(Node shape)
    {
        var toLandblock = shape.LocalMatrix * shape.VisualParent.LocalMatrix * shape.VisualParent.VisualParent.LocalMatrix;
        var points = shape.Mesh.Primitives.SelectMany(p => p.GetVertexAccessor("POSITION").AsVector3Array()).Select(p => Vector3.Transform(p, toLandblock)).ToArray();
        return (points.Aggregate(Vector3.Min), points.Aggregate(Vector3.Max));
    }

    /// <summary>Dat-axes bounds as glTF bounds: (x, y, z) → (x, z, −y), so y's min and max swap into z.</summary>
    private static (Vector3 Min, Vector3 Max) Gltf(Vector3 min, Vector3 max) =>
        (new Vector3(min.X, min.Z, -max.Y), new Vector3(max.X, max.Z, -min.Y));

    private static void AssertClose((Vector3 Min, Vector3 Max) expected, (Vector3 Min, Vector3 Max) actual, float tolerance = 1e-4f) =>
        Assert.True(Vector3.Distance(expected.Min, actual.Min) <= tolerance && Vector3.Distance(expected.Max, actual.Max) <= tolerance,
            $"expected {expected}, got {actual}");

    private static int PolygonTriangles(BspDump dump) => dump.Polygons.Where(p => p.Plane is not null).Sum(p => p.VertexIds.Count - 2);

    [Fact]
    public void Each_kind_of_shape_is_drawn_in_its_models_group_with_its_triangles_and_bounds()
    {
        using var scene = SceneFolder(HandBuilt());
        using var output = new TempDir();
        var printed = View(output, "--scene", scene.Path);
        Assert.Equal(["0x1234-compiled.glb", "0x1234-compiled.svg"], output.Files());
        Assert.Contains("view 0x1234-compiled: spheres 1, fallback-cylinder 1, part-boxes 1, part-hulls 1, retail 1 shape(s)", printed);
        var path = Path.Combine(output.Path, "0x1234-compiled.glb");
        var root = ViewCommandTests.ReadStrict(path).DefaultScene.VisualChildren.Single();
        Assert.StartsWith("Landblock 0x1234 compiled: ", root.Name);
        Assert.Equal(Vector3.Zero, root.LocalTransform.Translation);
        Assert.Equal(new Vector3(0x12 * 192, 0x34 * 192, 0), ViewCommandTests.WorldOrigin(root));
        Assert.Equal(["spheres", "fallback-cylinder", "part-boxes", "part-hulls", "retail"], root.VisualChildren.Select(g => g.Name));
        Node Only(string group) => root.VisualChildren.Single(g => ViewCommandTests.Layer(g) == group).VisualChildren.Single();
        Assert.Equal("spheres: #0 Setup 0x02000001", Only("spheres").Name);
        Assert.Equal("fallback-cylinder: #1 Setup 0x02000002", Only("fallback-cylinder").Name);
        Assert.Equal("part-boxes: #2 GfxObj 0x01000003", Only("part-boxes").Name);
        Assert.Equal("part-hulls: #3 GfxObj 0x01000004", Only("part-hulls").Name);
        Assert.Equal("retail: #4 Setup 0x020019FF", Only("retail").Name);
        Assert.Equal(["part-boxes: #2 GfxObj 0x01000003: part 0 (GfxObj 0x01000003) as box"], Only("part-boxes").VisualChildren.Select(n => n.Name));

        // The box: 6 faces of 2 triangles. Its half extents (0.5, 0.25, 0.5) turned 90° about z span x ±0.25,
        // y ±0.5, z 0..1 about (0, 0, 0.5); the part's scale 2 and offset (1, 0, 0) make x 0.5..1.5, y −1..1,
        // z 0..2; the object stands at (6, 2, 0).
        var box = Only("part-boxes").VisualChildren.Single();
        Assert.Equal(12, ViewCommandTests.Triangles(box));
        AssertClose(Gltf(new Vector3(6.5f, 1, 0), new Vector3(7.5f, 3, 2)), LandblockBounds(box));
        // The tetrahedron: 4 faces of one triangle each; the unit corner scaled 2, at (10, 2, 0).
        var hull = Only("part-hulls").VisualChildren.Single();
        Assert.Equal(4, ViewCommandTests.Triangles(hull));
        AssertClose(Gltf(new Vector3(10, 2, 0), new Vector3(12, 4, 2)), LandblockBounds(hull));
        // The cylinder: 32 quads round, two 32-gon caps; r 0.3, 1.8 tall, at (4, 2, 0).
        var cylinder = Only("fallback-cylinder").VisualChildren.Single();
        Assert.Equal(2 * 32 + 2 * (32 - 2), ViewCommandTests.Triangles(cylinder));
        AssertClose(Gltf(new Vector3(3.7f, 1.7f, 0), new Vector3(4.3f, 2.3f, 1.8f)), LandblockBounds(cylinder));
        // The sphere: 16 bands of 32, a triangle fan at each pole; r 0.5 round (0, 0, 0.5), at (2, 2, 0).
        var sphere = Only("spheres").VisualChildren.Single();
        Assert.Equal(2 * 32 + 14 * 32 * 2, ViewCommandTests.Triangles(sphere));
        AssertClose(Gltf(new Vector3(1.5f, 1.5f, 0), new Vector3(2.5f, 2.5f, 1)), LandblockBounds(sphere));
        // The BSP part: the committed leaf's physics polygons, n − 2 triangles each, at (16, 2, 0).
        var leaf = BspFileReader.Read(File.ReadAllText(Path.Combine(scene.Path, FileFormats.Bsp.PathFor(Leaf))));
        var part = Only("retail").VisualChildren.Single();
        Assert.Equal(PolygonTriangles(leaf), ViewCommandTests.Triangles(part));
        var used = leaf.Polygons.Where(p => p.Plane is not null).SelectMany(p => p.VertexIds).ToHashSet();
        var corners = leaf.Vertices.Where(v => used.Contains(v.Id)).Select(v => v.Position + new Vector3(16, 2, 0)).ToArray();
        AssertClose(Gltf(corners.Aggregate(Vector3.Min), corners.Aggregate(Vector3.Max)), LandblockBounds(part));

        Assert.False(ModelRoot.Validate(path).HasErrors);
        var svg = File.ReadAllText(Path.Combine(output.Path, "0x1234-compiled.svg"));
        foreach (var model in new[] { "spheres", "fallback-cylinder", "part-boxes", "part-hulls", "retail" })
            Assert.Contains($">{model}: 1 shape<", svg);
        Assert.Contains("#2 GfxObj 0x01000003 (part-boxes)", svg);
        Assert.Contains("1 placed object(s) have no shape to draw", svg);
    }

    [Fact]
    public void The_compiled_sample_landblock_puts_every_object_in_its_chosen_models_group_in_world_frames()
    {
        using var scene = CompiledSample();
        using var output = new TempDir();
        View(output, "--scene", scene.Path, "--landblock", "0xA9B4");
        var loaded = CompiledScene.Load(scene.Path);
        var root = ViewCommandTests.ReadStrict(Path.Combine(output.Path, "0xA9B4-compiled.glb")).DefaultScene.VisualChildren.Single();
        var models = ModelLadder.Names.Where(m => loaded.Objects.Any(o => o.Model == m)).ToArray();
        Assert.Contains("part-hulls", models);
        Assert.Equal([.. models, "cells"], root.VisualChildren.Select(g => g.Name));

        var json = File.ReadAllText(Path.Combine(scene.Path, FileFormats.CompiledScene.Path));
        var worldOrigin = System.Text.Json.JsonDocument.Parse(json).RootElement.GetProperty("worldOrigin").EnumerateArray().Select(e => e.GetSingle()).ToArray();
        Assert.Equal(new Vector3(worldOrigin[0], worldOrigin[1], worldOrigin[2]), ViewCommandTests.WorldOrigin(root));
        foreach (var o in loaded.Objects)
        {
            var kind = o.Kind == SceneObjectKind.Setup ? "Setup" : "GfxObj";
            var node = root.VisualChildren.Single(g => ViewCommandTests.Layer(g) == o.Model).VisualChildren.Single(n => n.Name == $"{o.Model}: #{o.Index} {kind} {JsonIds.Format(o.Id)}");
            Assert.Equal(GlbWriter.ToGltf(o.LandblockFrame.Position), node.LocalTransform.Translation);
            Assert.Equal(o.Shapes, node.VisualChildren.Count());
        }
        // The column's hull: each face a fan of n − 2 triangles, its bounds its vertices posed in the landblock.
        var column = loaded.Objects.Single(o => o.Model == "part-hulls");
        var hull = root.VisualChildren.Single(g => ViewCommandTests.Layer(g) == "part-hulls").VisualChildren.Single().VisualChildren.Single();
        var hullJson = System.Text.Json.JsonDocument.Parse(json).RootElement.GetProperty("objects").EnumerateArray()
            .Single(o => o.GetProperty("index").GetInt32() == column.Index).GetProperty("shapes")[0];
        Assert.Equal(hullJson.GetProperty("faces").EnumerateArray().Sum(f => f.GetProperty("vertices").GetArrayLength() - 2), ViewCommandTests.Triangles(hull));
        static Vector3 Vec(System.Text.Json.JsonElement v) => new(v[0].GetSingle(), v[1].GetSingle(), v[2].GetSingle());
        var poseJson = hullJson.GetProperty("pose");
        var q = poseJson.GetProperty("orientation");
        var pose = new PartPose(Vec(poseJson.GetProperty("position")),
            new Quaternion(q.GetProperty("x").GetSingle(), q.GetProperty("y").GetSingle(), q.GetProperty("z").GetSingle(), q.GetProperty("w").GetSingle()),
            poseJson.GetProperty("scale").GetSingle());
        var frame = new PartPose(column.LandblockFrame.Position, column.LandblockFrame.Rotation, 1f);
        var posed = hullJson.GetProperty("vertices").EnumerateArray().Select(v => frame.ToEntity(pose.ToEntity(Vec(v)))).ToArray();
        AssertClose(Gltf(posed.Aggregate(Vector3.Min), posed.Aggregate(Vector3.Max)), LandblockBounds(hull), 1e-3f);
        // Each cell: its retail polygons from its dump, in the cell's frame.
        var cells = root.VisualChildren.Single(g => ViewCommandTests.Layer(g) == "cells").VisualChildren.ToArray();
        Assert.Equal(loaded.Cells.Select(c => $"cells: cell {JsonIds.Format(c.CellId)}"), cells.Select(n => n.Name));
        foreach (var (cell, node) in loaded.Cells.Zip(cells))
        {
            var dump = BspFileReader.Read(File.ReadAllText(Path.Combine(scene.Path, CompiledSceneWriter.CellBspPath(cell.CellId))));
            Assert.Equal(PolygonTriangles(dump), ViewCommandTests.Triangles(node.VisualChildren.Single()));
            Assert.Equal(GlbWriter.ToGltf(cell.LandblockFrame.Position), node.LocalTransform.Translation);
        }
    }

    [RasterisingFact]
    public void The_svg_rasterises_with_the_box_and_the_hull_in_their_colours_where_the_file_puts_them()
    {
        var json = HandBuilt();
        using var scene = SceneFolder(json);
        using var output = new TempDir();
        View(output, "--scene", scene.Path);
        var svgPath = Path.Combine(output.Path, "0x1234-compiled.svg");
        var drawing = CompiledSceneDrawing.Read(json, file => BspFileReader.Read(File.ReadAllText(Path.Combine(scene.Path, file))));
        var view = ViewSceneBuilder.ForCompiledScene(drawing, []);
        Assert.Equal(ThreeViewSvg.Write(view), File.ReadAllText(svgPath));
        var layout = ThreeViewSvg.Layout(view);
        var pngPath = Path.Combine(output.Path, "scene.png");
        ViewCommandTests.Rasterise(svgPath, pngPath);
        var png = PngImage.Read(File.ReadAllBytes(pngPath));

        // From above, the middle of the box (x 6.5..7.5, y 1..3) is part-boxes' blue; inside the hull's
        // footprint (the triangle x, y ≥ its corner (10, 2), x + y ≤ 14) part-hulls' orange.
        var (bx, by) = layout.Top(new Vector3(7, 2.2f, 1));
        var blue = png.At((int)bx, (int)by);
        Assert.True(blue.B > blue.R + 40, $"pixel ({bx:0}, {by:0}) should be part-boxes' blue, is {blue}");
        var (hx, hy) = layout.Top(new Vector3(10.5f, 2.5f, 1));
        var orange = png.At((int)hx, (int)hy);
        Assert.True(orange.R > orange.B + 40, $"pixel ({hx:0}, {hy:0}) should be part-hulls' orange, is {orange}");
        // Beside the box, between it and the hull: the panel's near-white.
        var (ex, ey) = layout.Top(new Vector3(8.7f, 3.5f, 1));
        var empty = png.At((int)ex, (int)ey);
        Assert.True(empty.R > 240 && empty.G > 240 && empty.B > 240, $"pixel ({ex:0}, {ey:0}) should be empty, is {empty}");
    }

    [Fact]
    public void Chart_failures_are_markers_in_the_frame_of_the_compiled_object_they_belong_to()
    {
        using var scene = SceneFolder(HandBuilt());
        using var chart = new TempDir();
        // One false block of part-boxes beside the box (entity frame), as `chart` lists it.
        File.WriteAllText(Path.Combine(chart.Path, "failures.csv"),
            "setup,model,rank,failure,kind,line,offset_m,x,y,z,radius\n0x01000003,part-boxes,1,false_block,face,,,1.6,0,1,0.5\n");
        using var output = new TempDir();
        View(output, "--scene", scene.Path, "--chart", chart.Path);
        var root = ViewCommandTests.ReadStrict(Path.Combine(output.Path, "0x1234-compiled.glb")).DefaultScene.VisualChildren.Single();
        Assert.Equal(["spheres", "fallback-cylinder", "part-boxes", "part-hulls", "retail", "part-boxes false blocks"], root.VisualChildren.Select(ViewCommandTests.Layer));
        var marker = root.VisualChildren.Last().VisualChildren.Single();
        Assert.Equal("part-boxes false blocks: #2 GfxObj 0x01000003", marker.Name);
        // The probe at (1.6, 0, 1) in the object's frame, which stands at (6, 2, 0).
        // A false block is a cube, centre to corner MarkerRadius.
        var half = ViewSceneBuilder.MarkerRadius / MathF.Sqrt(3);
        AssertClose(Gltf(new Vector3(7.6f, 2, 1) - new Vector3(half), new Vector3(7.6f, 2, 1) + new Vector3(half)),
            LandblockBounds(marker.VisualChildren.Single()));
    }

    [Fact]
    public void The_same_folder_gives_the_same_bytes_whatever_the_culture_and_where_it_is()
    {
        var json = HandBuilt();
        using var sceneA = SceneFolder(json);
        using var sceneB = SceneFolder(json);
        using var first = new TempDir();
        using var second = new TempDir();
        View(first, "--scene", sceneA.Path);
        var culture = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");
            View(second, "--scene", sceneB.Path);
        }
        finally
        {
            CultureInfo.CurrentCulture = culture;
        }
        Assert.Equal(first.Files(), second.Files());
        foreach (var file in first.Files())
            Assert.True(File.ReadAllBytes(Path.Combine(first.Path, file)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(second.Path, file))), file);
        var again = View(first, "--scene", sceneA.Path);
        Assert.Equal(2, again.Split('\n').Count(l => l.StartsWith("unchanged ", StringComparison.Ordinal)));
    }

    [Fact]
    public void A_bad_or_mismatched_compiled_scene_is_one_line_and_writes_nothing()
    {
        using var output = new TempDir();
        using var empty = new TempDir();
        using var notJson = SceneFolder("{ not json");
        using var otherFormat = SceneFolder(HandBuilt().Replace("acshadow.compiled-scene/1", "acshadow.scene/1"));
        using var otherFile = SceneFolder(HandBuilt(leafFile: "gfxobjs/0x010044B6.bsp.json"));
        using var outside = SceneFolder(HandBuilt(leafFile: "../0x010044B5.bsp.json"));
        // An object with no model is not drawn, but the consumer library still reads its shapes: only dumps inside the folder.
        using var outsideUndrawn = SceneFolder(HandBuilt().Replace("\"model\": null, \"shapes\": []",
            "\"model\": null, \"shapes\": [" + """{"type": "bsp", "source": "part 0", "gfxObjId": "0x010044B5", "pose": {"position": [0, 0, 0], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}, "scale": 1}, "file": "../../0x010044B5.bsp.json"}""" + "]"));
        using var unknownModel = SceneFolder(HandBuilt(boxModel: "boxes"));
        using var noExtents = SceneFolder(HandBuilt().Replace("\"halfExtents\"", "\"halfExtent\""));
        using var swapped = SceneFolder(HandBuilt());
        File.Copy(Path.Combine(swapped.Path, FileFormats.Bsp.PathFor(Post)), Path.Combine(swapped.Path, FileFormats.Bsp.PathFor(Leaf)), overwrite: true);
        using var missing = SceneFolder(HandBuilt());
        File.Delete(Path.Combine(missing.Path, FileFormats.Bsp.PathFor(Leaf)));
        using var good = SceneFolder(HandBuilt());
        var cases = new (string[] Args, int Code, string Expected)[]
        {
            (["--scene", Path.Combine(empty.Path, "nowhere")], 2, "is not a folder"),
            (["--scene", empty.Path], 2, "has no compiled-scene.json"),
            (["--scene", notJson.Path], 2, "is not a compiled scene this version reads"),
            (["--scene", otherFormat.Path], 2, "not \"acshadow.compiled-scene/1\""),
            (["--scene", otherFile.Path], 2, "not gfxobjs/0x010044B5.bsp.json (the file its id names)"),
            (["--scene", outside.Path], 2, "its BSP dump is \"../0x010044B5.bsp.json\", not gfxobjs/0x010044B5.bsp.json"),
            (["--scene", outsideUndrawn.Path], 2, "\"../../0x010044B5.bsp.json\" is not a BSP dump `acshadow scene` writes"),
            (["--scene", noExtents.Path], 2, "missing field \"halfExtents\""),
            (["--scene", unknownModel.Path], 2, "model \"boxes\" is none of the ladder's"),
            (["--scene", swapped.Path], 2, "holds the tree of 0x010044B6, not of 0x010044B5"),
            (["--scene", missing.Path], 2, "gfxobjs/0x010044B5.bsp.json, which is missing"),
            (["--scene", good.Path, "--landblock", "0xA9B4"], 4, "compiles landblock 0x1234, not 0xA9B4"),
            (["--scene", good.Path, "--dat", good.Path], 2, "drop --dat and --cell-dat"),
            (["--scene", good.Path, "--setup", "0x020019FF"], 2, "drop --setup and --fixtures"),
            (["--scene", good.Path, "--pose", "placement"], 2, "drop --scale, --pose"),
        };
        foreach (var (args, code, expected) in cases)
        {
            var run = CliRun.Of(["view", .. args, "--out", output.Path]);
            Assert.True(code == run.ExitCode, $"{string.Join(' ', args)}: exit {run.ExitCode}: {run.Error}");
            Assert.Contains(expected, Assert.Single(run.ErrorLines));
        }
        Assert.Empty(output.Files());
    }

    [Fact]
    public void The_committed_drawing_of_the_compiled_sample_is_what_view_writes()
    {
        using var scene = CompiledSample(walked: true);
        using var output = new TempDir();
        View(output, "--scene", scene.Path);
        var docs = Path.Combine(RepositoryRoot.Path, "docs", "view");
        foreach (var name in new[] { "0xA9B4-compiled.glb", "0xA9B4-compiled.svg" })
            Assert.True(File.ReadAllBytes(Path.Combine(docs, name)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(output.Path, name))),
                $"docs/view/{name} is stale: rerun scripts/regenerate-drawings.sh");
    }
}
