using AcShadow.Core.Export;
using AcShadow.Fixtures.Batch;

namespace AcShadow.Core.Batch;

/// <summary>Names of index.json (docs/formats.md, schemas/acshadow.index-1.schema.json).</summary>
public static class BatchIndexFormat
{
    public const string Format = AcShadow.Fixtures.FileFormats.Index;
}
