using AcShadow.Core.Json;

namespace AcShadow.Core.Scenes;

/// <summary>Names of the scene file (docs/batch.md, schemas/acshadow.scene-1.schema.json).</summary>
public static class SceneFileFormat
{
    public const string Format = "acshadow.scene/1";

    /// <summary>Relative path of a landblock's scene file inside an output folder.</summary>
    public static string PathFor(uint landBlockInfoId) => $"scenes/{JsonIds.Format(landBlockInfoId)}.scene.json";

    /// <summary>A file's path relative to a scene file (scenes/, setups/ and gfxobjs/ are siblings).</summary>
    public static string Reference(string outputRelativePath) => "../" + outputRelativePath;

    public static string KindName(SceneObjectKind kind) => kind switch
    {
        SceneObjectKind.Setup => "setup",
        SceneObjectKind.GfxObj => "gfxObj",
        _ => "other",
    };

    public static string PlacedByName(ScenePlacedBy by) => by == ScenePlacedBy.Object ? "object" : "building";
}
