using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Formats;

/// <summary>Writes a Setup's <see cref="ShadowShapeSet"/> as the canonical shadow file (docs/formats.md).</summary>
public static class ShadowFileWriter
{
    public static byte[] Write(Setup setup, ShadowShapeSet set) => CanonicalJsonWriter.WriteUtf8(ToJson(setup, set));

    /// <param name="bspReference">How a shape names its BSP file; by default relative to setups/ (the shadow file's folder).</param>
    public static JsonObj ToJson(Setup setup, ShadowShapeSet set, Func<uint, string>? bspReference = null) => new JsonObj()
        .Add("format", FileFormats.Shadow.Format)
        .Add("setupId", JsonIds.Format(set.SetupId))
        .Add("policy", set.Policy.Name())
        .Add("placement", new JsonObj().Add("requested", set.Placement.Requested).Add("used", set.Placement.Used))
        .Add("pose", Pose(set.Pose))
        .Add("entityScale", set.EntityScale)
        .Add("setup", SetupFacts(setup, set))
        .Add("shapes", JsonArr.Of(set.Shapes, s => Shape(s, bspReference ?? BspReference)))
        .Add("diagnostics", JsonArr.Of(set.Diagnostics, d => new JsonObj().Add("code", d.Code).Add("message", d.Message)));

    /// <summary>A BSP dump's path relative to a shadow file (setups/ and gfxobjs/ are siblings).</summary>
    private static string BspReference(uint gfxObjId) => "../" + FileFormats.Bsp.PathFor(gfxObjId);

    internal static JsonObj Pose(PoseProvenance p) => new JsonObj()
        .Add("policy", p.Policy)
        .Add("source", p.Source)
        .Add("motionTable", Id(p.MotionTableId))
        .Add("motionTableFrom", p.MotionTableFrom)
        .Add("style", Id(p.Style))
        .Add("substate", Id(p.Substate))
        .Add("animation", Id(p.AnimationId))
        .Add("frame", p.Frame is { } frame ? JsonNum.Of(frame) : JsonNull.Value)
        .Add("doorState", p.DoorState)
        .Add("ethereal", p.Ethereal)
        .Add("differsFromPlacement", p.DiffersFromPlacement);

    private static string? Id(uint? id) => id is { } v ? JsonIds.Format(v) : null;

    private static JsonObj SetupFacts(Setup setup, ShadowShapeSet set) => new JsonObj()
        .Add("flags", (long)setup.Flags)
        .Add("flagNames", JsonArr.Of(FlagNames(setup.Flags)))
        .Add("parts", JsonArr.Of(setup.Parts.Select(JsonIds.Format)))
        .Add("defaultScale", JsonArr.Of(setup.DefaultScale, JsonArr.Of))
        .Add("placements", JsonArr.Of(setup.PlacementFrames.Select(p => p.Name)))
        .Add("defaultAnimation", JsonIds.Format(setup.DefaultAnimation))
        .Add("defaultMotionTable", JsonIds.Format(setup.DefaultMotionTable))
        .Add("radius", setup.Radius)
        .Add("height", setup.Height)
        .Add("stepUpHeight", setup.StepUpHeight)
        .Add("stepDownHeight", setup.StepDownHeight)
        .Add("cylSpheres", JsonArr.Of(setup.CylSpheres, c => new JsonObj().Add("origin", c.Origin).Add("radius", c.Radius).Add("height", c.Height)))
        .Add("spheres", JsonArr.Of(setup.Spheres, JsonShapes.Sphere))
        .Add("hasPhysicsBsp", set.PartsHavePhysicsBsp)
        .Add("hasPhysicsBspFlag", setup.Flags.HasFlag(SetupFlags.HasPhysicsBsp));

    private static IEnumerable<string> FlagNames(SetupFlags flags) =>
        Enum.GetValues<SetupFlags>().Where(f => f != SetupFlags.None && flags.HasFlag(f)).Select(f => f.ToString());

    internal static JsonNode Shape(ShadowShape s, Func<uint, string> bspReference)
    {
        var obj = new JsonObj()
            .Add("source", s.Source.Name())
            .Add("sourceIndex", s.SourceIndex)
            .Add("gfxObjId", s.GfxObjId is { } id ? JsonIds.Format(id) : null)
            .Add("collisionType", s.CollisionType.Name())
            .Add("localPosition", s.LocalPosition)
            .Add("localRotation", JsonShapes.Quaternion(s.LocalRotation))
            .Add("scale", s.Scale)
            .Add("radius", s.Radius)
            .Add("cylHeight", s.CylHeight);
        if (s.CollisionType == CollisionType.Bsp && s.GfxObjId is { } gfx)
        {
            if (s.LocalSphere is { } sphere) obj.Add("localSphere", JsonShapes.Sphere(sphere));
            obj.Add("bsp", bspReference(gfx));
        }
        return obj;
    }
}
