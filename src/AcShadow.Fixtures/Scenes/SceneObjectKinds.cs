namespace AcShadow.Fixtures.Scenes;

/// <summary>The names scene files give a <see cref="SceneObjectKind"/>: "setup", "gfxObj", "other".</summary>
internal static class SceneObjectKinds
{
    public static string Name(this SceneObjectKind kind) => kind switch
    {
        SceneObjectKind.Setup => "setup",
        SceneObjectKind.GfxObj => "gfxObj",
        SceneObjectKind.Other => "other",
        _ => throw new ArgumentOutOfRangeException(nameof(kind)),
    };

    public static SceneObjectKind Parse(string name) => name switch
    {
        "setup" => SceneObjectKind.Setup,
        "gfxObj" => SceneObjectKind.GfxObj,
        "other" => SceneObjectKind.Other,
        _ => throw new FormatException($"kind \"{name}\" is not setup, gfxObj or other"),
    };
}
