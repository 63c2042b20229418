using System.Buffers;
using System.Globalization;
using System.Numerics;
using System.Text.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// A <see cref="ViewScene"/> as one binary glTF 2.0 file, written here (JSON by <see cref="Utf8JsonWriter"/>,
/// the chunks by <see cref="GlbContainer"/>) so the Native AOT binary carries no glTF library. Nodes, in
/// depth-first order: the scene's root (carrying a landblock's world origin), one node per group, one per
/// object in it (its frame), one per shape with its mesh. Units are metres. The dat is Z-up (x east, y north,
/// z up); glTF is Y-up with +Z toward the viewer, so every position, normal and rotation axis is converted
/// explicitly as (x, y, z)_dat → (x, z, −y)_glTF, a proper rotation (−90° about x): winding and handedness
/// are kept. Materials: one per group and sidedness (glTF sets double-sidedness per material), in order of
/// first use. No timestamps, no <c>extras</c>; the same scene gives the same bytes.
/// </summary>
public static class GlbWriter
{
    public const string Generator = "acshadow view";

    public static Vector3 ToGltf(Vector3 dat) => new(dat.X, dat.Z, -dat.Y);

    public static Quaternion ToGltf(Quaternion dat) => new(dat.X, dat.Z, -dat.Y, dat.W);

    private sealed record Node(string Name, Vector3 Translation, Quaternion Rotation, int? Mesh)
    {
        public List<int> Children { get; } = [];
    }

    private sealed record Primitive(int Position, int Normal, int Indices, int Material);

    private sealed record Mesh(string Name, IReadOnlyList<Primitive> Primitives);

    private sealed record Material(string Name, Vector4 BaseColour, bool DoubleSided);

    public static byte[] Write(ViewScene view)
    {
        var nodes = new List<Node>();
        var meshes = new List<Mesh>();
        var materials = new List<Material>();
        var data = new GltfBinaryData();
        var meshOf = new Dictionary<ViewShape, int?>(ReferenceEqualityComparer.Instance);

        int AddNode(Node node, int? parent)
        {
            nodes.Add(node);
            if (parent is { } p) nodes[p].Children.Add(nodes.Count - 1);
            return nodes.Count - 1;
        }

        var root = AddNode(new Node(view.Name, ToGltf(view.WorldOrigin), Quaternion.Identity, null), null);
        foreach (var group in view.Groups)
        {
            var groupNode = AddNode(new Node(group.Name, Vector3.Zero, Quaternion.Identity, null), root);
            var groupMaterials = new GroupMaterials(group, materials);
            foreach (var o in group.Objects)
            {
                var objectNode = AddNode(new Node($"{group.Name}: {o.Name}", ToGltf(o.Frame.Position), ToGltf(o.Frame.Rotation), null), groupNode);
                var prefix = group.Objects.Count == 1 ? "" : o.Name.Split(' ')[0] + " ";
                foreach (var shape in o.Shapes)
                {
                    var name = $"{group.Name}: {prefix}{shape.Name}";
                    if (!meshOf.TryGetValue(shape, out var mesh)) meshOf[shape] = mesh = AddMesh(meshes, data, name, shape, groupMaterials);
                    AddNode(new Node(name, Vector3.Zero, Quaternion.Identity, mesh), objectNode);
                }
            }
        }

        var json = new ArrayBufferWriter<byte>();
        using (var writer = new Utf8JsonWriter(json))
        {
            writer.WriteStartObject();
            writer.WriteStartObject("asset");
            writer.WriteString("generator", Generator);
            writer.WriteString("version", "2.0");
            writer.WriteEndObject();
            writer.WriteNumber("scene", 0);
            writer.WriteStartArray("scenes");
            writer.WriteStartObject();
            writer.WriteString("name", view.Name);
            writer.WriteStartArray("nodes");
            writer.WriteNumberValue(root);
            writer.WriteEndArray();
            writer.WriteEndObject();
            writer.WriteEndArray();
            WriteNodes(writer, nodes);
            WriteMeshes(writer, meshes);
            WriteMaterials(writer, materials);
            data.WriteJson(writer);
            writer.WriteEndObject();
        }
        return GlbContainer.Pack(json.WrittenSpan, data.Bytes);
    }

    /// <summary>A shape's mesh: a primitive for its one-sided and one for its two-sided triangles, whichever it has; none when it has no triangles.</summary>
    private static int? AddMesh(List<Mesh> meshes, GltfBinaryData data, string name, ViewShape shape, GroupMaterials materials)
    {
        var primitives = new List<Primitive>();
        if (!shape.OneSided.IsEmpty) primitives.Add(AddPrimitive(data, shape.OneSided, materials.OneSided));
        if (!shape.TwoSided.IsEmpty) primitives.Add(AddPrimitive(data, shape.TwoSided, materials.TwoSided));
        if (primitives.Count == 0) return null;
        meshes.Add(new Mesh(name, primitives));
        return meshes.Count - 1;
    }

    private static Primitive AddPrimitive(GltfBinaryData data, TriangleMesh triangles, int material) =>
        new(data.AddVectors(triangles.Positions, bounds: true), data.AddVectors(triangles.Normals, bounds: false), data.AddIndices(triangles.Indices), material);

    private static void WriteNodes(Utf8JsonWriter json, List<Node> nodes)
    {
        json.WriteStartArray("nodes");
        foreach (var node in nodes)
        {
            json.WriteStartObject();
            json.WriteString("name", node.Name);
            if (node.Mesh is { } mesh) json.WriteNumber("mesh", mesh);
            if (node.Rotation != Quaternion.Identity) GltfJson.WriteQuaternion(json, "rotation", node.Rotation);
            if (node.Translation != Vector3.Zero) GltfJson.WriteVector(json, "translation", node.Translation);
            if (node.Children.Count > 0)
            {
                json.WriteStartArray("children");
                foreach (var child in node.Children) json.WriteNumberValue(child);
                json.WriteEndArray();
            }
            json.WriteEndObject();
        }
        json.WriteEndArray();
    }

    private static void WriteMeshes(Utf8JsonWriter json, List<Mesh> meshes)
    {
        if (meshes.Count == 0) return;
        json.WriteStartArray("meshes");
        foreach (var mesh in meshes)
        {
            json.WriteStartObject();
            json.WriteString("name", mesh.Name);
            json.WriteStartArray("primitives");
            foreach (var primitive in mesh.Primitives)
            {
                json.WriteStartObject();
                json.WriteStartObject("attributes");
                json.WriteNumber("POSITION", primitive.Position);
                json.WriteNumber("NORMAL", primitive.Normal);
                json.WriteEndObject();
                json.WriteNumber("indices", primitive.Indices);
                json.WriteNumber("material", primitive.Material);
                json.WriteNumber("mode", 4); // TRIANGLES
                json.WriteEndObject();
            }
            json.WriteEndArray();
            json.WriteEndObject();
        }
        json.WriteEndArray();
    }

    private static void WriteMaterials(Utf8JsonWriter json, List<Material> materials)
    {
        if (materials.Count == 0) return;
        json.WriteStartArray("materials");
        foreach (var material in materials)
        {
            json.WriteStartObject();
            json.WriteString("name", material.Name);
            json.WriteStartObject("pbrMetallicRoughness");
            json.WriteStartArray("baseColorFactor");
            GltfJson.WriteFloat(json, material.BaseColour.X);
            GltfJson.WriteFloat(json, material.BaseColour.Y);
            GltfJson.WriteFloat(json, material.BaseColour.Z);
            GltfJson.WriteFloat(json, material.BaseColour.W);
            json.WriteEndArray();
            GltfJson.WriteFloat(json, "metallicFactor", 0f);
            GltfJson.WriteFloat(json, "roughnessFactor", 0.9f);
            json.WriteEndObject();
            if (material.DoubleSided) json.WriteBoolean("doubleSided", true);
            json.WriteEndObject();
        }
        json.WriteEndArray();
    }

    /// <summary>A group's materials, added when first used: its colour, matte, one-sided or two-sided.</summary>
    private sealed class GroupMaterials(ViewGroup group, List<Material> materials)
    {
        private int? _oneSided;
        private int? _twoSided;

        public int OneSided => _oneSided ??= Add(new Material(group.Name, Rgba(group.Colour), DoubleSided: false));
        public int TwoSided => _twoSided ??= Add(new Material(group.Name + " (two-sided)", Rgba(group.Colour), DoubleSided: true));

        private int Add(Material material)
        {
            materials.Add(material);
            return materials.Count - 1;
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
