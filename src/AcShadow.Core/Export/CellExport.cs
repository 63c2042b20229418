using AcShadow.Core.Export;
using AcShadow.Core.Formats;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// One EnvCell's export: its cell file (null when its Environment or cell structure is missing), the BSP
/// dumps of the bare GfxObjs placed inside it, what could not be described, and its diagnostics.
/// </summary>
public sealed record CellExport(
    uint CellId,
    OutputFile? File,
    IReadOnlyList<OutputFile> BspFiles,
    IReadOnlyList<FileEntry> BspEntries,
    IReadOnlyList<SkippedItem> Skipped,
    IReadOnlyList<Diagnostic> Diagnostics,
    int ObjectCount)
{
    public string? Path => File?.RelativePath;
}
