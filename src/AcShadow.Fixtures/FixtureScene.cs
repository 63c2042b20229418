using System.Numerics;
using System.Text.Json;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Scenes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Fixtures;

/// <summary>scene.json read back: a landblock's placed objects in world frames, and its indoor cells.</summary>
public sealed record FixtureScene(uint LandblockId, Vector3 WorldOrigin, ShapePolicy Policy, float EntityScale, IReadOnlyList<ScenePlacement> Objects)
{
    /// <summary>The landblock's EnvCells (empty when the batch ran with --no-cells or the landblock has none).</summary>
    public IReadOnlyList<SceneCellFile> Cells { get; init; } = [];

    public static FixtureScene Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Scene, "scene.json");
        var policyText = BspFileReader.Str(root, "policy");
        if (!ShapePolicies.TryParse(policyText, out var policy)) throw new FormatException($"policy \"{policyText}\" is not retail or union");
        var objects = BspFileReader.Arr(root, "objects").Select(o =>
        {
            var frame = BspFileReader.Prop(o, "worldFrame");
            var file = BspFileReader.Prop(o, "file");
            var shapes = o.TryGetProperty("shapes", out var s) ? s.EnumerateArray().Select(ShadowFileReader.ReadShape).ToArray() : [];
            return new ScenePlacement(BspFileReader.Int(o, "index"), Id(o, "id"), SceneObjectKinds.Parse(BspFileReader.Str(o, "kind")),
                BspFileReader.Vec(BspFileReader.Prop(frame, "origin")), BspFileReader.Quat(BspFileReader.Prop(frame, "orientation")),
                file.ValueKind == JsonValueKind.Null ? null : file.GetString(), shapes);
        }).ToArray();
        var cells = root.TryGetProperty("cells", out var c)
            ? c.EnumerateArray().Select(e =>
            {
                var file = BspFileReader.Prop(e, "file");
                return new SceneCellFile(Id(e, "id"), file.ValueKind == JsonValueKind.Null ? null : file.GetString());
            }).ToArray()
            : [];
        return new FixtureScene(Id(root, "landblockId"), BspFileReader.Vec(BspFileReader.Prop(root, "worldOrigin")), policy,
            BspFileReader.Float(root, "entityScale"), objects) { Cells = cells };
    }

    private static uint Id(JsonElement e, string name) =>
        JsonIds.TryParse(BspFileReader.Str(e, name), out var id) ? id : throw new FormatException($"{name} is not a hex id");
}
