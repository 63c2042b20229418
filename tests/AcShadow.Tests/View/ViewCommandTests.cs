using System.Text.RegularExpressions;
using System.Diagnostics;
using System.Globalization;
using System.Numerics;
using AcShadow.Analysis.View;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures;
using AcShadow.Fixtures.Collision;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Shapes;
using AcShadow.Tests.Fixtures;
using AcShadow.Tests.Support;
using SharpGLTF.Schema2;
using SharpGLTF.Validation;

namespace AcShadow.Tests.View;

/// <summary>
/// `view` on the sample door: the glb read back with SharpGLTF (strict validation) holds each model's
/// shapes in its group with the triangle counts and bounds the committed shadow file and BSP dumps give;
/// the svg rasterises (rsvg-convert) with the leaf drawn where the shadow file puts it; output is
/// byte-identical run to run and across cultures.
/// </summary>
public sealed class ViewCommandTests
{
    private const uint Door = 0x020019FF;

    private static string Run(TempDir dir, params string[] args)
    {
        var run = CliRun.Of(["view", .. args, "--out", dir.Path]);
        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Error}");
        GltfValidator.AssertValid(dir.Path);
        return run.Out;
    }

    internal static ModelRoot ReadStrict(string path) =>
        ModelRoot.ParseGLB(File.ReadAllBytes(path), new ReadSettings { Validation = ValidationMode.Strict });

    private static SetupFixture CommittedDoor() => SetupFixture.Load(CommittedFixturesTests.RepositoryFixtures(), Door);

    /// <summary>The retail shape's physics polygons posed in the entity frame, as the collision reference poses them.</summary>
    private static Vector3[] PosedVertices(SetupFixture door, ShadowShape shape)
    {
        var pose = new PartPose(shape.LocalPosition, shape.LocalRotation, shape.Scale);
        var dump = door.Bsps[shape.GfxObjId!.Value];
        var used = dump.Polygons.Where(p => p.Plane is not null).SelectMany(p => p.VertexIds).ToHashSet();
        return dump.Vertices.Where(v => used.Contains(v.Id)).Select(v => pose.ToEntity(v.Position)).ToArray();
    }

    private static (Vector3 Min, Vector3 Max) WorldBounds(Node node)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var primitive in node.Mesh.Primitives)
            foreach (var p in primitive.GetVertexAccessor("POSITION").AsVector3Array())
            {
                var w = Vector3.Transform(p, node.WorldMatrix);
                min = Vector3.Min(min, w);
                max = Vector3.Max(max, w);
            }
        return (min, max);
    }

    /// <summary>A group node's layer name: its node name without the note in parentheses ("union (…)" is "union").</summary>
    internal static string Layer(Node group) => group.Name.Split(" (")[0];

    /// <summary>The root's extras: where the view's origin is in the world (dat axes).</summary>
    internal static Vector3 WorldOrigin(Node root)
    {
        var origin = root.Extras!["worldOrigin"]!.AsArray();
        return new Vector3((float)origin[0]!, (float)origin[1]!, (float)origin[2]!);
    }

    internal static int Triangles(Node node) => node.Mesh.Primitives.Sum(p => p.GetTriangleIndices().Count());

    [Fact]
    public void The_door_glb_holds_each_model_in_its_group_with_the_shadow_files_triangles_and_bounds()
    {
        using var dir = new TempDir();
        Run(dir, "--setup", "0x020019FF");
        Assert.Equal(["0x020019FF.glb", "0x020019FF.svg"], dir.Files());
        var path = Path.Combine(dir.Path, "0x020019FF.glb");
        var model = ReadStrict(path);
        Assert.Equal(GlbWriter.Generator, model.Asset.Generator);

        var root = Assert.Single(model.DefaultScene.VisualChildren);
        Assert.Equal("Setup 0x020019FF", root.Name);
        Assert.Equal(Vector3.Zero, WorldOrigin(root));
        Assert.Equal(["retail", "union", "fallback-cylinder", "spheres"], root.VisualChildren.Select(Layer));
        // Union's three parts are retail's: drawn once, in retail's layer, and union's name says so.
        Assert.Equal("union (3 shape(s) the same as retail's are drawn in the retail layer only)", root.VisualChildren.ElementAt(1).Name);
        string[] Shapes(string group) => root.VisualChildren.Single(g => Layer(g) == group).VisualChildren.Single().VisualChildren.Select(n => n.Name).ToArray();
        Assert.Equal(["retail: part 0 (GfxObj 0x010044B5)", "retail: part 1 (GfxObj 0x010044B6)", "retail: part 2 (GfxObj 0x010044B6)"], Shapes("retail"));
        Assert.Equal(["union: Sphere 0 as cylinder"], Shapes("union"));
        Assert.Equal(["fallback-cylinder: Setup Radius x Height"], Shapes("fallback-cylinder"));
        Assert.Equal(["spheres: Sphere 0"], Shapes("spheres"));
        Assert.Equal(6, model.LogicalMeshes.Count);
        // The reference is opaque; every other layer blends over it, so retail shows through.
        Assert.All(model.LogicalMaterials, m => Assert.Equal(m.Name.StartsWith("retail", StringComparison.Ordinal) ? AlphaMode.OPAQUE : AlphaMode.BLEND, m.Alpha));

        // Against the committed shadow file: each retail part's triangles (a polygon of n vertices is n − 2)
        // and bounds (its posed physics vertices, dat Z-up turned to glTF Y-up as (x, z, −y)).
        var door = CommittedDoor();
        var retail = root.VisualChildren.Single(g => Layer(g) == "retail").VisualChildren.Single().VisualChildren.ToArray();
        for (var i = 0; i < door.Shadow.Shapes.Count; i++)
        {
            var shape = door.Shadow.Shapes[i];
            var dump = door.Bsps[shape.GfxObjId!.Value];
            Assert.Equal(dump.Polygons.Where(p => p.Plane is not null).Sum(p => p.VertexIds.Count - 2), Triangles(retail[i]));
            var vertices = PosedVertices(door, shape).Select(GlbWriter.ToGltf).ToArray();
            var (min, max) = WorldBounds(retail[i]);
            AssertClose(vertices.Aggregate(Vector3.Min), min);
            AssertClose(vertices.Aggregate(Vector3.Max), max);
        }
        // The soda can: the Setup's Radius × Height (0.141 × 0.2) standing at the origin; glTF's up is y.
        var can = root.VisualChildren.Single(g => Layer(g) == "fallback-cylinder").VisualChildren.Single().VisualChildren.Single();
        var (canMin, canMax) = WorldBounds(can);
        AssertClose(new Vector3(-0.141f, 0f, -0.141f), canMin);
        AssertClose(new Vector3(0.141f, 0.2f, 0.141f), canMax);
        Assert.Equal(2 * UnitCircle.Steps + 2 * (UnitCircle.Steps - 2), Triangles(can));

        var validation = ModelRoot.Validate(path);
        Assert.False(validation.HasErrors, string.Join('\n', validation.Errors));
    }

    [Fact]
    public void The_same_input_gives_the_same_bytes_whatever_the_culture()
    {
        using var first = new TempDir();
        using var second = new TempDir();
        Run(first, "--setup", "0x020019FF", "--setup", "0x02001000", "--landblock", "0xA9B4");
        var culture = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");
            Run(second, "--setup", "0x020019FF", "--setup", "0x02001000", "--landblock", "0xA9B4");
        }
        finally
        {
            CultureInfo.CurrentCulture = culture;
        }
        Assert.Equal(6, first.Files().Length);
        Assert.Equal(first.Files(), second.Files());
        foreach (var file in first.Files())
            Assert.True(File.ReadAllBytes(Path.Combine(first.Path, file)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(second.Path, file))), file);
        var again = Run(first, "--setup", "0x020019FF", "--setup", "0x02001000", "--landblock", "0xA9B4");
        Assert.Equal(6, again.Split('\n').Count(l => l.StartsWith("unchanged ", StringComparison.Ordinal)));
    }

    [Fact]
    public void The_fixtures_view_reads_only_json_and_draws_what_the_dat_view_draws()
    {
        using var fromDat = new TempDir();
        using var fromFixtures = new TempDir();
        Run(fromDat, "--setup", "0x020019FF");
        Run(fromFixtures, "--fixtures", CommittedFixturesTests.RepositoryFixtures(), "--setup", "0x020019FF");
        var dat = ReadStrict(Path.Combine(fromDat.Path, "0x020019FF.glb")).DefaultScene.VisualChildren.Single();
        var fixtures = ReadStrict(Path.Combine(fromFixtures.Path, "0x020019FF.glb")).DefaultScene.VisualChildren.Single();
        // A retail shadow file does not say what union would pose, so that layer is left out.
        Assert.Equal(["retail", "fallback-cylinder", "spheres"], fixtures.VisualChildren.Select(Layer));
        foreach (var group in fixtures.VisualChildren)
        {
            var shapes = group.VisualChildren.Single().VisualChildren.ToArray();
            var same = dat.VisualChildren.Single(g => Layer(g) == Layer(group)).VisualChildren.Single().VisualChildren.ToArray();
            Assert.Equal(same.Select(n => n.Name), shapes.Select(n => n.Name));
            Assert.Equal(same.Select(Triangles), shapes.Select(Triangles));
            Assert.Equal(same.Select(WorldBounds), shapes.Select(WorldBounds));
        }
    }

    [Fact]
    public void Every_fixture_and_the_landblock_are_viewed_in_world_frames()
    {
        using var dir = new TempDir();
        var fixtures = CommittedFixturesTests.RepositoryFixtures();
        Run(dir, "--fixtures", fixtures);
        var set = FixtureSet.Open(fixtures);
        var setups = Directory.GetFiles(Path.Combine(fixtures, "setups")).Length;
        Assert.Equal(2 * (setups + 1), dir.Files().Length);
        var model = ReadStrict(Path.Combine(dir.Path, "0xA9B4.glb"));
        var root = model.DefaultScene.VisualChildren.Single();
        var scene = set.Scene!;
        // The root stays at the origin (a viewer opens on the geometry); the world origin is in its extras.
        Assert.Equal(Vector3.Zero, root.LocalTransform.Translation);
        Assert.Equal(scene.WorldOrigin, WorldOrigin(root));
        var retail = root.VisualChildren.Single(g => Layer(g) == "retail");
        var placed = scene.Objects.Where(o => o.File is not null).ToArray();
        // The four outdoor objects and the one cell 0xA9B40100 places (#4), numbered on as `scene` numbers it.
        Assert.Equal(placed.Length + 1, retail.VisualChildren.Count());
        Assert.Single(retail.VisualChildren, n => n.Name.StartsWith("retail: #4 Setup 0x02003300", StringComparison.Ordinal));
        Assert.Equal(["cells: cell 0xA9B40100", "cells: cell 0xA9B40101"], root.VisualChildren.Single(g => Layer(g) == "cells").VisualChildren.Select(n => n.Name));
        foreach (var o in placed)
        {
            var node = retail.VisualChildren.Single(n => n.Name.StartsWith($"retail: #{o.Index} ", StringComparison.Ordinal));
            AssertClose(GlbWriter.ToGltf(o.WorldFrame.Position - scene.WorldOrigin), node.WorldMatrix.Translation, 0.01f);
        }
    }

    [Fact]
    public void Chart_failures_become_markers_in_their_own_groups()
    {
        using var chart = new TempDir();
        var run = CliRun.Of("chart", "--setup", "0x020019FF", "--out", chart.Path, "--quiet");
        Assert.Equal(0, run.ExitCode);
        using var dir = new TempDir();
        Run(dir, "--setup", "0x020019FF", "--chart", chart.Path);
        var failures = ChartFailure.ParseCsv(File.ReadAllText(Path.Combine(chart.Path, "failures.csv")));
        var passes = failures.Count(f => f.Model == "fallback-cylinder" && f.FalsePass);
        Assert.True(passes > 0, "the soda can lets probes through the doorway");
        var root = ReadStrict(Path.Combine(dir.Path, "0x020019FF.glb")).DefaultScene.VisualChildren.Single();
        var group = root.VisualChildren.Single(g => Layer(g) == "fallback-cylinder false passes");
        Assert.Equal($"fallback-cylinder false passes ({passes} probe(s) of radius 0.5 m, marked at their centres)", group.Name);
        var markers = group.VisualChildren.Single().VisualChildren.Single();
        Assert.Equal($"fallback-cylinder false passes: {passes} false pass{(passes == 1 ? "" : "es")} of fallback-cylinder (probe r 0.5 m)", markers.Name);
        // Each false pass is an octahedron (8 triangles); each false block a cube (12).
        Assert.Equal(passes * 8, Triangles(markers));
        // A model's two verdicts sit side by side, in the model's colour.
        var layers = root.VisualChildren.Select(Layer).ToList();
        Assert.Equal(layers.IndexOf("fallback-cylinder false passes") + 1, layers.IndexOf("fallback-cylinder false blocks"));
        var svg = File.ReadAllText(Path.Combine(dir.Path, "0x020019FF.svg"));
        Assert.Contains("<g id=\"layer-fallback-cylinder-false-passes\"><title>fallback-cylinder false passes (", svg);
        // Three views of each false pass as a diamond in fallback-cylinder's colour, and one in the legend.
        Assert.Equal(3 * passes + 1, Regex.Matches(svg, "<polygon [^>]*fill=\"#D55E00\" stroke=\"#ffffff\"").Count);
    }

    [RasterisingFact]
    public void The_svg_rasterises_with_the_door_leaf_drawn_where_the_shadow_file_puts_it()
    {
        using var dir = new TempDir();
        Run(dir, "--setup", "0x020019FF");
        var svgPath = Path.Combine(dir.Path, "0x020019FF.svg");
        var pngPath = Path.Combine(dir.Path, "door.png");
        Rasterise(svgPath, pngPath);
        var png = PngImage.Read(File.ReadAllBytes(pngPath));

        using var dat = SampleDat.OpenPortal();
        var scene = ViewSceneBuilder.ForSetup(ViewSubjects.FromDat(dat.ReadSetup(Door)!, dat.ReadGfxObj, new ShapeBuildOptions(ShapePolicy.Retail), dat), []);
        Assert.Equal(ThreeViewSvg.Write(scene), File.ReadAllText(svgPath));
        var layout = ThreeViewSvg.Layout(scene);
        Assert.Equal((int)Math.Ceiling(layout.Width), png.Width);

        // The leaf (part 0), from the committed shadow file: the middle of its posed physics vertices.
        var door = CommittedDoor();
        var leaf = PosedVertices(door, door.Shadow.Shapes[0]);
        var (lo, hi) = (leaf.Aggregate(Vector3.Min), leaf.Aggregate(Vector3.Max));
        var centre = (lo + hi) / 2;
        var (fx, fy) = layout.Front(centre with { Z = lo.Z + (hi.Z - lo.Z) * 0.3f });
        var (tx, ty) = layout.Top(centre with { X = lo.X + (hi.X - lo.X) * 0.3f });
        var (sx, sy) = layout.Side(centre with { Z = lo.Z + (hi.Z - lo.Z) * 0.7f });
        foreach (var (x, y) in new[] { (fx, fy), (tx, ty), (sx, sy) })
        {
            var (r, g, b, a) = png.At((int)x, (int)y);
            Assert.True(a == 255 && r < 215 && Math.Abs(r - b) < 40, $"pixel ({x:0}, {y:0}) should be the leaf's grey, is ({r}, {g}, {b}, {a})");
        }
        // Above the leaf and the posts, inside the front panel: the panel's own near-white.
        var (ex, ey) = layout.Front(centre with { Z = hi.Z + 0.12f });
        var empty = png.At((int)ex, (int)ey);
        Assert.True(empty.R > 240 && empty.G > 240 && empty.B > 240, $"pixel ({ex:0}, {ey:0}) above the door should be empty, is {empty}");
    }

    [Fact]
    public void The_committed_drawing_of_the_sample_door_is_what_view_writes()
    {
        using var dir = new TempDir();
        Run(dir, "--setup", "0x020019FF");
        var docs = Path.Combine(Path.GetDirectoryName(CommittedFixturesTests.RepositoryFixtures())!, "docs", "view");
        foreach (var name in new[] { "0x020019FF.glb", "0x020019FF.svg" })
            Assert.True(File.ReadAllBytes(Path.Combine(docs, name)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(dir.Path, name))),
                $"docs/view/{name} is stale: rerun `acshadow view --setup 0x020019FF --out docs/view`");
    }

    internal static void Rasterise(string svg, string png)
    {
        var start = new ProcessStartInfo("rsvg-convert", ["-o", png, svg]) { RedirectStandardError = true };
        Process? process;
        try
        {
            process = Process.Start(start);
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            throw new InvalidOperationException("rsvg-convert is not installed: apt-get install librsvg2-bin (.ci/run installs it)", e);
        }
        using (process)
        {
            var error = process!.StandardError.ReadToEnd();
            process.WaitForExit();
            Assert.True(process.ExitCode == 0, $"rsvg-convert failed: {error}");
        }
    }

    private static void AssertClose(Vector3 expected, Vector3 actual, float tolerance = 1e-5f) =>
        Assert.True(Vector3.Distance(expected, actual) <= tolerance, $"expected {expected}, got {actual}");
}
