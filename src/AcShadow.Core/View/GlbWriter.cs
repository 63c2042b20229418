using System.Buffers.Binary;
using System.Globalization;
using System.Numerics;
using SharpGLTF.Schema2;
using SharpGLTF.Transforms;

namespace AcShadow.Core.View;

/// <summary>
/// A <see cref="ViewScene"/> as one binary glTF 2.0 file (SharpGLTF writes it). Nodes: the scene's root
/// (carrying a landblock's world origin), one node per group, one per object in it (its frame), one per
/// shape with its mesh. Units are metres. The dat is Z-up (x east, y north, z up); glTF is Y-up with +Z
/// toward the viewer, so every position, normal and rotation axis is converted explicitly as
/// (x, y, z)_dat → (x, z, −y)_glTF, a proper rotation (−90° about x): winding and handedness are kept.
/// Materials: one per group and sidedness (glTF sets double-sidedness per material). No timestamps; the same
/// scene gives the same bytes. No <c>extras</c>: SharpGLTF's setter for them is not trimming-safe, and the
/// tool ships as a Native AOT binary.
/// </summary>
public static class GlbWriter
{
    public const string Generator = "acshadow view";

    public static Vector3 ToGltf(Vector3 dat) => new(dat.X, dat.Z, -dat.Y);

    public static Quaternion ToGltf(Quaternion dat) => new(dat.X, dat.Z, -dat.Y, dat.W);

    public static byte[] Write(ViewScene view)
    {
        var model = ModelRoot.CreateModel();
        model.Asset.Generator = Generator;
        var scene = model.UseScene(view.Name);
        var root = scene.CreateNode(view.Name);
        if (view.WorldOrigin != Vector3.Zero) root.LocalTransform = new AffineTransform(null, null, ToGltf(view.WorldOrigin));
        var meshes = new Dictionary<ViewShape, Mesh>(ReferenceEqualityComparer.Instance);
        foreach (var group in view.Groups)
        {
            var groupNode = root.CreateNode(group.Name);
            var materials = new Materials(model, group);
            foreach (var o in group.Objects)
            {
                var objectNode = groupNode.CreateNode($"{group.Name}: {o.Name}");
                if (o.Frame != ViewFrame.Identity) objectNode.LocalTransform = new AffineTransform(null, ToGltf(o.Frame.Rotation), ToGltf(o.Frame.Position));
                var prefix = group.Objects.Count == 1 ? "" : o.Name.Split(' ')[0] + " ";
                foreach (var shape in o.Shapes)
                {
                    var name = $"{group.Name}: {prefix}{shape.Name}";
                    if (!meshes.TryGetValue(shape, out var mesh)) meshes[shape] = mesh = CreateMesh(model, name, shape, materials);
                    objectNode.CreateNode(name).Mesh = mesh;
                }
            }
        }
        var bytes = model.WriteGLB(new WriteSettings { Validation = SharpGLTF.Validation.ValidationMode.Strict, MergeBuffers = true });
        return bytes.ToArray();
    }

    private static Mesh CreateMesh(ModelRoot model, string name, ViewShape shape, Materials materials)
    {
        var mesh = model.CreateMesh(name);
        AddPrimitive(model, mesh, shape.OneSided, materials.OneSided);
        AddPrimitive(model, mesh, shape.TwoSided, materials.TwoSided);
        return mesh;
    }

    private static void AddPrimitive(ModelRoot model, Mesh mesh, TriangleMesh triangles, Lazy<Material> material)
    {
        if (triangles.IsEmpty) return;
        var primitive = mesh.CreatePrimitive();
        primitive.DrawPrimitiveType = PrimitiveType.TRIANGLES;
        primitive.SetVertexAccessor("POSITION", Vectors(model, triangles.Positions));
        primitive.SetVertexAccessor("NORMAL", Vectors(model, triangles.Normals));
        var indices = new byte[triangles.Indices.Count * 4];
        for (var i = 0; i < triangles.Indices.Count; i++) BinaryPrimitives.WriteUInt32LittleEndian(indices.AsSpan(i * 4), (uint)triangles.Indices[i]);
        var view = model.UseBufferView(indices, 0, indices.Length, 0, BufferMode.ELEMENT_ARRAY_BUFFER);
        var accessor = model.CreateAccessor();
        accessor.SetIndexData(view, 0, triangles.Indices.Count, IndexEncodingType.UNSIGNED_INT);
        primitive.SetIndexAccessor(accessor);
        primitive.Material = material.Value;
    }

    private static Accessor Vectors(ModelRoot model, IReadOnlyList<Vector3> vectors)
    {
        var bytes = new byte[vectors.Count * 12];
        for (var i = 0; i < vectors.Count; i++)
        {
            var v = ToGltf(vectors[i]);
            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(i * 12), v.X);
            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(i * 12 + 4), v.Y);
            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(i * 12 + 8), v.Z);
        }
        var view = model.UseBufferView(bytes, 0, bytes.Length, 0, BufferMode.ARRAY_BUFFER);
        var accessor = model.CreateAccessor();
        accessor.SetVertexData(view, 0, vectors.Count, SharpGLTF.Memory.AttributeFormat.Float3);
        return accessor;
    }

    /// <summary>A group's materials, made when first used: its colour, matte, one-sided or two-sided.</summary>
    private sealed class Materials(ModelRoot model, ViewGroup group)
    {
        public Lazy<Material> OneSided { get; } = new(() => Create(model, group.Name, group.Colour, doubleSided: false));
        public Lazy<Material> TwoSided { get; } = new(() => Create(model, group.Name + " (two-sided)", group.Colour, doubleSided: true));

        private static Material Create(ModelRoot model, string name, string colour, bool doubleSided)
        {
            var material = model.CreateMaterial(name);
            material.InitializePBRMetallicRoughness();
            material.DoubleSided = doubleSided;
            var baseColour = material.FindChannel("BaseColor")!.Value;
            baseColour.Color = Rgba(colour);
            var metallicRoughness = material.FindChannel("MetallicRoughness")!.Value;
            metallicRoughness.SetFactor("MetallicFactor", 0f);
            metallicRoughness.SetFactor("RoughnessFactor", 0.9f);
            return material;
        }

        /// <summary>"#rrggbb" as linear RGBA, as glTF's baseColorFactor is linear.</summary>
        private static Vector4 Rgba(string hex)
        {
            float Channel(int at)
            {
                var srgb = int.Parse(hex.AsSpan(at, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture) / 255f;
                // Rounded so a last-bit difference in the C runtime's pow cannot change the file.
                return (float)Math.Round(srgb <= 0.04045f ? srgb / 12.92 : Math.Pow((srgb + 0.055) / 1.055, 2.4), 4);
            }
            return new Vector4(Channel(1), Channel(3), Channel(5), 1f);
        }
    }
}
