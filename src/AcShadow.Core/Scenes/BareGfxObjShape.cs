using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Formats;
using AcShadow.Core.Json;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Formats;
using AcShadow.Fixtures.Json;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Scenes;

/// <summary>
/// The collision shape of a bare GfxObj a landblock places. Retail makes such a static a physics object
/// with a one-part part array and no placement frames, so the part sits at the object's origin; this
/// runs exactly that one-part Setup through <see cref="ShadowShapeBuilder"/> and the shadow writer,
/// rather than a second shape code path.
/// </summary>
public static class BareGfxObjShape
{
    public static ShadowShapeSet Build(GfxObj gfx, Func<uint, GfxObj?> gfxObjs, ShapeBuildOptions options) =>
        ShadowShapeBuilder.Build(OnePartSetup(gfx), gfxObjs, options);

    /// <summary>The shapes array as the shadow file writes it, each BSP reference relative to the scene file (the folder root).</summary>
    public static JsonNode ShapesJson(GfxObj gfx, ShadowShapeSet set) =>
        ShadowFileWriter.ToJson(OnePartSetup(gfx), set, id => FileFormats.Bsp.PathFor(id))
            .Members.First(m => m.Key == "shapes").Value;

    /// <summary>The flag agrees with the part, so the builder reports no mismatch that the dat never stored.</summary>
    public static Setup OnePartSetup(GfxObj gfx) => new(
        gfx.Id, gfx.HasPhysics ? SetupFlags.HasPhysicsBsp : SetupFlags.None, [gfx.Id], [], [], [], [], [], 0f, 0f, 0f, 0f, default, default);
}
