using AcShadow.Core.Export;

namespace AcShadow.Core.Batch;

/// <summary>Names of index.json (docs/formats.md, schemas/acshadow.index-1.schema.json).</summary>
public static class BatchIndexFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.Index;

    public static string KindName(OutputKind kind) => kind switch
    {
        OutputKind.Shadow => "shadow",
        OutputKind.Bsp => "bsp",
        OutputKind.Scene => "scene",
        OutputKind.AcdreamGfxObj => "acdream",
        OutputKind.Cell => "cell",
        OutputKind.AcdreamCell => "acdream-cell",
        _ => throw new ArgumentOutOfRangeException(nameof(kind)),
    };
}
