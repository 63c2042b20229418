using System.Buffers.Binary;
using System.Globalization;
using System.Numerics;
using System.Text;
using AcShadow.Analysis.View;
using AcShadow.Fixtures.Geometry;
using SharpGLTF.Schema2;
using SharpGLTF.Validation;

namespace AcShadow.Tests.View;

/// <summary>
/// acshadow writes its .glb files itself; SharpGLTF (a test-only dependency) reads them back with strict
/// validation, so the writer and its checker are independent. The container's bytes are worked out by hand
/// from the GLB 2.0 layout: header "glTF", version 2, total length; chunks of (length, type, data) with the
/// JSON padded by spaces and the binary data by zeros to 4 bytes.
/// </summary>
public sealed class GlbWriterTests
{
    [Fact]
    public void The_container_is_a_header_then_a_space_padded_json_chunk_then_a_zero_padded_bin_chunk()
    {
        var bytes = GlbContainer.Pack("{}"u8, [1, 2, 3, 4, 5]);
        byte[] expected =
        [
            (byte)'g', (byte)'l', (byte)'T', (byte)'F', 2, 0, 0, 0, 40, 0, 0, 0,
            4, 0, 0, 0, (byte)'J', (byte)'S', (byte)'O', (byte)'N', (byte)'{', (byte)'}', (byte)' ', (byte)' ',
            8, 0, 0, 0, (byte)'B', (byte)'I', (byte)'N', 0, 1, 2, 3, 4, 5, 0, 0, 0,
        ];
        Assert.Equal(expected, bytes);
        // No binary data: no BIN chunk at all (an empty chunk would declare a buffer of length 0).
        Assert.Equal(12 + 8 + 4, GlbContainer.Pack("{}"u8, []).Length);
    }

    private static readonly Vector3 Up = Vector3.UnitZ;

    /// <summary>One group, two placed objects sharing one shape: a one-sided triangle and a two-sided quad (dat axes).</summary>
    private static ViewScene Scene()
    {
        var oneSided = new TriangleMesh();
        oneSided.AddPolygon([new(0, 0, 0), new(1, 0, 0), new(0, 2, 0)], Up);
        var twoSided = new TriangleMesh();
        twoSided.AddPolygon([new(0, 0, 0), new(0, 0, 3), new(1, 0, 3), new(1, 0, 0)], -Vector3.UnitY);
        var shape = new ViewShape("part 0 GfxObj 0x01000001", oneSided, twoSided, new PointsOutline([], FalsePass: true), Vector3.Zero);
        var turned = Quaternion.CreateFromAxisAngle(Up, MathF.PI / 2);
        ViewObject[] objects =
        [
            new("#1 Setup 0x02000001", new Frame(new Vector3(10, 20, 1.5f), turned), [shape]),
            new("#2 Setup 0x02000001", Frame.Identity, [shape]),
        ];
        return new ViewScene("0xA9B4", "title", new Vector3(192, 384, 0), [new ViewGroup("retail", "", "#ffffff", objects) { Filled = true }], []);
    }

    private static ModelRoot Read(byte[] glb) => ModelRoot.ParseGLB(glb, new ReadSettings { Validation = ValidationMode.Strict });

    [Fact]
    public void A_scene_reads_back_strictly_with_its_hierarchy_shared_meshes_and_materials()
    {
        var model = Read(GlbWriter.Write(Scene()));
        Assert.Equal(GlbWriter.Generator, model.Asset.Generator);
        var root = Assert.Single(model.DefaultScene.VisualChildren);
        Assert.Equal("title", root.Name);
        Assert.Equal(Vector3.Zero, root.LocalTransform.Translation);
        Assert.Equal(new Vector3(192, 384, 0), ViewCommandTests.WorldOrigin(root));
        var group = Assert.Single(root.VisualChildren);
        Assert.Equal("retail", group.Name);
        Assert.Equal(["retail: #1 Setup 0x02000001", "retail: #2 Setup 0x02000001"], group.VisualChildren.Select(n => n.Name));
        var shapes = group.VisualChildren.Select(o => Assert.Single(o.VisualChildren)).ToArray();
        Assert.Equal(["retail: part 0 GfxObj 0x01000001", "retail: part 0 GfxObj 0x01000001"], shapes.Select(n => n.Name));
        // A shape placed twice is one mesh, named where it was first placed.
        Assert.Same(shapes[0].Mesh, shapes[1].Mesh);
        Assert.Equal("retail: part 0 GfxObj 0x01000001", Assert.Single(model.LogicalMeshes).Name);

        var primitives = shapes[0].Mesh.Primitives;
        Assert.Equal(2, primitives.Count);
        Assert.Equal([3, 4], primitives.Select(p => p.GetVertexAccessor("POSITION").Count));
        Assert.Equal([1, 2], primitives.Select(p => p.GetTriangleIndices().Count()));
        Assert.Equal([("retail", false), ("retail (two-sided)", true)], primitives.Select(p => (p.Material.Name, p.Material.DoubleSided)));
        foreach (var material in model.LogicalMaterials)
        {
            Assert.Equal(Vector4.One, material.FindChannel("BaseColor")!.Value.Color);
            Assert.Equal(0.9f, material.FindChannel("MetallicRoughness")!.Value.GetFactor("RoughnessFactor"));
            Assert.Equal(0f, material.FindChannel("MetallicRoughness")!.Value.GetFactor("MetallicFactor"));
        }
    }

    [Fact]
    public void Positions_normals_and_frames_turn_from_dat_z_up_to_gltf_y_up_as_x_z_minus_y()
    {
        var scene = Scene();
        var model = Read(GlbWriter.Write(scene));
        var shape = scene.Groups[0].Objects[0].Shapes[0];
        var primitives = model.LogicalMeshes[0].Primitives;
        foreach (var (primitive, triangles) in primitives.Zip([shape.OneSided, shape.TwoSided]))
        {
            Assert.Equal(triangles.Positions.Select(p => new Vector3(p.X, p.Z, -p.Y)), primitive.GetVertexAccessor("POSITION").AsVector3Array());
            Assert.Equal(triangles.Normals.Select(n => new Vector3(n.X, n.Z, -n.Y)), primitive.GetVertexAccessor("NORMAL").AsVector3Array());
        }
        // Dat up (+z) is glTF up (+y); a quarter turn about dat z is a quarter turn about glTF y.
        Assert.Equal(Vector3.UnitY, primitives[0].GetVertexAccessor("NORMAL").AsVector3Array()[0]);
        var placed = model.DefaultScene.VisualChildren.Single().VisualChildren.Single().VisualChildren.First();
        Assert.Equal(new Vector3(10, 1.5f, -20), placed.LocalTransform.Translation);
        var rotation = placed.LocalTransform.Rotation;
        var expected = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2);
        Assert.True(Math.Abs(Quaternion.Dot(expected, rotation)) > 1 - 1e-6f, $"rotation {rotation}");
        // The dat point one metre east of the object, turned a quarter about up, lands one metre north: glTF −z.
        var world = Vector3.Transform(new Vector3(1, 0, 0), placed.LocalMatrix);
        Assert.True(Vector3.Distance(new Vector3(10, 1.5f, -21), world) < 1e-5f, $"{world}");
    }

    [Fact]
    public void Floats_are_written_shortest_round_trip_and_the_bytes_do_not_depend_on_the_culture()
    {
        var bytes = GlbWriter.Write(Scene());
        var json = Encoding.UTF8.GetString(bytes, 20, (int)BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(12)));
        Assert.Contains("\"roughnessFactor\":0.9", json, StringComparison.Ordinal);
        Assert.Contains("\"translation\":[10,1.5,-20]", json, StringComparison.Ordinal);
        Assert.DoesNotContain("0.89999", json, StringComparison.Ordinal);
        var culture = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = CultureInfo.GetCultureInfo("de-DE");
            Assert.Equal(bytes, GlbWriter.Write(Scene()));
        }
        finally
        {
            CultureInfo.CurrentCulture = culture;
        }
    }
}
