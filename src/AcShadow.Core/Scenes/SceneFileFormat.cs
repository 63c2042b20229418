using AcShadow.Core.Json;

namespace AcShadow.Core.Scenes;

/// <summary>Names of the scene file (docs/formats.md, schemas/acshadow.scene-1.schema.json).</summary>
public static class SceneFileFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.Scene;

    /// <summary>
    /// The scene file's path inside an output folder: one run describes at most one landblock, as it writes
    /// one index.json. It sits at the root beside setups/ and gfxobjs/, so the output-relative paths of the
    /// files it names are also relative to it.
    /// </summary>
    public const string Path = "scene.json";

    public static string PlacedByName(ScenePlacedBy by) => by switch
    {
        ScenePlacedBy.Object => "object",
        ScenePlacedBy.Building => "building",
        _ => "cell",
    };
}
