using System.Text.Json;
using AcShadow.Fixtures.Geometry;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;
using static AcShadow.Fixtures.Json.JsonFields;

namespace AcShadow.Fixtures.Formats;

/// <summary>
/// Reads the shapes and the pose of a shadow file back, so a consumer of the fixtures (or the collision
/// reference) works from exactly what the tool wrote. The Setup facts block is informational and not
/// read back.
/// </summary>
internal static class ShadowFileReader
{
    public static ShadowShapeSet Read(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        FormatCheck.Require(root, FileFormats.Shadow, "shadow file");
        if (!JsonIds.TryParse(Str(root, "setupId"), out var setupId)) throw new FormatException("setupId is not a hex id");
        if (!ShapePolicies.TryParse(Str(root, "policy"), out var policy)) throw new FormatException("unknown policy");
        var placement = Prop(root, "placement");
        var shapes = Arr(root, "shapes").Select(ReadShape).ToArray();
        var diagnostics = Arr(root, "diagnostics").Select(d => new Diagnostic(Str(d, "code"), Str(d, "message"))).ToArray();
        var setup = Prop(root, "setup");
        return new ShadowShapeSet(setupId, policy,
            new PlacementResolution(Str(placement, "requested"), Str(placement, "used")),
            Float(root, "entityScale"), Prop(setup, "hasPhysicsBsp").GetBoolean(), shapes, diagnostics) { Pose = ReadPose(Prop(root, "pose")) };
    }

    private static PoseProvenance ReadPose(JsonElement p)
    {
        var source = Str(p, "source");
        if (source is not (PoseProvenance.PlacementSource or PoseProvenance.DefaultAnimationSource or PoseProvenance.MotionTableSource))
            throw new FormatException($"unknown pose source \"{source}\"");
        var frame = Prop(p, "frame");
        return new PoseProvenance(Str(p, "policy"), source, OptionalId(p, "motionTable"), OptionalStr(p, "motionTableFrom"),
            OptionalId(p, "style"), OptionalId(p, "substate"), OptionalId(p, "animation"),
            frame.ValueKind == JsonValueKind.Null ? null : frame.GetInt32(), OptionalStr(p, "doorState"),
            Prop(p, "ethereal").GetBoolean(), Prop(p, "differsFromPlacement").GetBoolean());
    }

    private static string? OptionalStr(JsonElement e, string name) => Prop(e, name) is { ValueKind: JsonValueKind.Null } ? null : Str(e, name);

    private static uint? OptionalId(JsonElement e, string name) => OptionalStr(e, name) is not { } text ? null
        : JsonIds.TryParse(text, out var id) ? id : throw new FormatException($"pose {name} is not a hex id");

    internal static ShadowShape ReadShape(JsonElement s)
    {
        var source = ShadowShapeNames.ParseSource(Str(s, "source"));
        var type = ShadowShapeNames.ParseCollisionType(Str(s, "collisionType"));
        var gfxElement = Prop(s, "gfxObjId");
        uint? gfx = gfxElement.ValueKind == JsonValueKind.Null ? null
            : JsonIds.TryParse(gfxElement.GetString(), out var g) ? g : throw new FormatException("gfxObjId is not a hex id");
        Sphere? local = s.TryGetProperty("localSphere", out var ls) ? Sphere(ls) : null;
        return new ShadowShape(source, Int(s, "sourceIndex"), gfx, type, Vec(Prop(s, "localPosition")), Quat(Prop(s, "localRotation")),
            Float(s, "scale"), Float(s, "radius"), Float(s, "cylHeight"), local);
    }
}
