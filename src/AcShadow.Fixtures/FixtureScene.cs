using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures;

/// <summary>scene.json read back: a landblock's placed objects in world frames, and its indoor cells.</summary>
public sealed record FixtureScene(uint LandblockId, Vector3 WorldOrigin, ShapePolicy Policy, float EntityScale, IReadOnlyList<PlacedObject> Objects)
{
    /// <summary>The landblock's EnvCells (empty when the batch ran with --no-cells or the landblock has none).</summary>
    internal IReadOnlyList<SceneCellFile> Cells { get; init; } = [];

    public static FixtureScene Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Scene, "scene.json");
        var policyText = Str(root, "policy");
        if (!ShapePolicies.TryParse(policyText, out var policy)) throw new FormatException($"policy \"{policyText}\" is not retail or union");
        var objects = Arr(root, "objects").Select(o =>
        {
            var file = Prop(o, "file");
            var shapes = o.TryGetProperty("shapes", out var s) ? s.EnumerateArray().Select(ShadowFileReader.ReadShape).ToArray() : [];
            return new PlacedObject(Int(o, "index"), Id(o, "id"), SceneObjectKinds.Parse(Str(o, "kind")),
                FrameOf(Prop(o, "landblockFrame")), FrameOf(Prop(o, "worldFrame")),
                file.ValueKind == JsonValueKind.Null ? null : file.GetString(), shapes);
        }).ToArray();
        var cells = root.TryGetProperty("cells", out var c)
            ? c.EnumerateArray().Select(e =>
            {
                var file = Prop(e, "file");
                return new SceneCellFile(Id(e, "id"), file.ValueKind == JsonValueKind.Null ? null : file.GetString());
            }).ToArray()
            : [];
        return new FixtureScene(Id(root, "landblockId"), Vec(Prop(root, "worldOrigin")), policy,
            Float(root, "entityScale"), objects) { Cells = cells };
    }
}
