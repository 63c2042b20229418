using System.Buffers;
using System.Globalization;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Text.Json;

namespace AcShadow.Analysis.View;

/// <summary>
/// A <see cref="ViewScene"/> as one binary glTF 2.0 file, written here (JSON by <see cref="Utf8JsonWriter"/>,
/// the chunks by <see cref="GlbContainer"/>) so the Native AOT binary carries no glTF library. Nodes, in
/// depth-first order: the scene's root (named by the view's title, so no viewer renames it for clashing with
/// the scene's name; at the origin, with the world origin of a landblock's corner and the warnings in its
/// <c>extras</c>, so a viewer opens on the geometry, not 47 km away), one node per group, one per object in
/// it (its frame), one per shape with its mesh. A mesh belongs to one layer: no two layers share one. Units are metres. The dat is Z-up (x east, y north,
/// z up); glTF is Y-up with +Z toward the viewer, so every position, normal and rotation axis is converted
/// explicitly as (x, y, z)_dat → (x, z, −y)_glTF, a proper rotation (−90° about x): winding and handedness
/// are kept. Materials: one per group and sidedness (glTF sets double-sidedness per material), in order of
/// first use; the reference layer's (and markers') are opaque, every other layer's translucent (alpha
/// blend, <see cref="OverlayAlpha"/>), so the reference shows through what is drawn over it. No
/// timestamps; the same scene gives the same bytes.
/// </summary>
public static class GlbWriter
{
    public const string Generator = "acshadow view";

    /// <summary>The opacity of a layer drawn over the reference.</summary>
    public const float OverlayAlpha = 0.3f;

    public static Vector3 ToGltf(Vector3 dat) => new(dat.X, dat.Z, -dat.Y);

    public static Quaternion ToGltf(Quaternion dat) => new(dat.X, dat.Z, -dat.Y, dat.W);

    private sealed record Node(string Name, Vector3 Translation, Quaternion Rotation, int? Mesh)
    {
        public List<int> Children { get; } = [];

        /// <summary>Writes the node's extras object, when it has one.</summary>
        public Action<Utf8JsonWriter>? Extras { get; init; }
    }

    private sealed record Primitive(int Position, int Normal, int Indices, int Material);

    private sealed record Mesh(string Name, IReadOnlyList<Primitive> Primitives);

    private sealed record Material(string Name, Vector4 BaseColour, bool DoubleSided, bool Blend);

    public static byte[] Write(ViewScene view)
    {
        var nodes = new List<Node>();
        var meshes = new List<Mesh>();
        var materials = new List<Material>();
        var data = new GltfBinaryData();
        var meshOf = new Dictionary<(ViewGroup, ViewShape), int?>(new LayerShapeComparer());

        int AddNode(Node node, int? parent)
        {
            nodes.Add(node);
            if (parent is { } p) nodes[p].Children.Add(nodes.Count - 1);
            return nodes.Count - 1;
        }

        var root = AddNode(new Node(view.Title, Vector3.Zero, Quaternion.Identity, null) { Extras = json => WriteRootExtras(json, view) }, null);
        foreach (var group in view.Groups)
        {
            var groupNode = AddNode(new Node(group.Title, Vector3.Zero, Quaternion.Identity, null), root);
            var groupMaterials = new GroupMaterials(group, materials);
            foreach (var o in group.Objects)
            {
                var objectNode = AddNode(new Node($"{group.Name}: {o.Name}", ToGltf(o.Frame.Position), ToGltf(o.Frame.Rotation), null), groupNode);
                // A landblock's shapes name their object ("#3 Setup …", "cell 0x…"), however many the layer holds.
                var prefix = o.Key is null ? "" : o.Name + ": ";
                foreach (var shape in o.Shapes)
                {
                    var name = $"{group.Name}: {prefix}{shape.Name}";
                    // A shape shared by objects placed twice shares its mesh within the layer, never across layers.
                    if (!meshOf.TryGetValue((group, shape), out var mesh)) meshOf[(group, shape)] = mesh = AddMesh(meshes, data, name, shape, groupMaterials);
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
            if (node.Extras is { } extras)
            {
                json.WriteStartObject("extras");
                extras(json);
                json.WriteEndObject();
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
            if (material.Blend) json.WriteString("alphaMode", "BLEND");
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

        private bool Blend => !group.Filled && group.FalsePass is null;

        public int OneSided => _oneSided ??= Add(new Material(group.Name, Rgba(group.Colour, Blend), DoubleSided: false, Blend));
        public int TwoSided => _twoSided ??= Add(new Material(group.Name + " (two-sided)", Rgba(group.Colour, Blend), DoubleSided: true, Blend));

        private int Add(Material material)
        {
            materials.Add(material);
            return materials.Count - 1;
        }

        /// <summary>"#rrggbb" as linear RGBA, as glTF's baseColorFactor is linear.</summary>
        private static Vector4 Rgba(string hex, bool blend)
        {
            float Channel(int at)
            {
                var srgb = int.Parse(hex.AsSpan(at, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture) / 255f;
                // Rounded so a last-bit difference in the C runtime's pow cannot change the file.
                return (float)Math.Round(srgb <= 0.04045f ? srgb / 12.92 : Math.Pow((srgb + 0.055) / 1.055, 2.4), 4);
            }
            return new Vector4(Channel(1), Channel(3), Channel(5), blend ? OverlayAlpha : 1f);
        }
    }

    /// <summary>The root's extras: the landblock corner's world position (dat axes, metres) the geometry is relative to, and the warnings.</summary>
    private static void WriteRootExtras(Utf8JsonWriter json, ViewScene view)
    {
        json.WriteString("axes", "dat (x east, y north, z up) turned to glTF as (x, z, -y)");
        json.WriteStartArray("worldOrigin");
        foreach (var v in new[] { view.WorldOrigin.X, view.WorldOrigin.Y, view.WorldOrigin.Z })
            GltfJson.WriteFloat(json, float.IsFinite(v) ? v : 0f);
        json.WriteEndArray();
        json.WriteStartArray("warnings");
        foreach (var w in view.Warnings) json.WriteStringValue(w);
        json.WriteEndArray();
    }

    /// <summary>A layer and a shape, both by reference.</summary>
    private sealed class LayerShapeComparer : IEqualityComparer<(ViewGroup, ViewShape)>
    {
        public bool Equals((ViewGroup, ViewShape) a, (ViewGroup, ViewShape) b) => ReferenceEquals(a.Item1, b.Item1) && ReferenceEquals(a.Item2, b.Item2);

        public int GetHashCode((ViewGroup, ViewShape) key) => HashCode.Combine(RuntimeHelpers.GetHashCode(key.Item1), RuntimeHelpers.GetHashCode(key.Item2));
    }
}
