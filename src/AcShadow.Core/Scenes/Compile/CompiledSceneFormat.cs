namespace AcShadow.Core.Scenes.Compile;

/// <summary>Names of the compiled scene's files (docs/formats.md, schemas/acshadow.compiled-scene-1.schema.json).</summary>
public static class CompiledSceneFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.CompiledScene;
    public const string Path = "compiled-scene.json";
    public const string ChartCsvPath = "scene-chart.csv";
    public const string ChartSvgPath = "scene-chart.svg";
}
