namespace AcShadow.Core.Scenes;

/// <summary>The names scene files give a <see cref="ScenePlacedBy"/>: "object", "building", "cell".</summary>
public static class ScenePlacedByNames
{
    public static string Name(this ScenePlacedBy by) => by switch
    {
        ScenePlacedBy.Object => "object",
        ScenePlacedBy.Building => "building",
        _ => "cell",
    };
}
