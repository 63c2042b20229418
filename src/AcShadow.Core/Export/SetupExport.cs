using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Formats;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// A Setup's export: its shadow file, the BSP dumps its shapes reference (their bytes in
/// <see cref="BspFiles"/>, or, when the engine streams dumps, the entries of what was written in
/// <see cref="BspEntries"/>), and every diagnostic.
/// </summary>
public sealed record SetupExport(
    Setup Setup,
    ShadowShapeSet Set,
    OutputFile Shadow,
    IReadOnlyList<OutputFile> BspFiles,
    IReadOnlyList<FileEntry> BspEntries,
    IReadOnlyList<Diagnostic> Diagnostics)
{
    public IEnumerable<OutputFile> Files => BspFiles.Prepend(Shadow);

    /// <summary>The motion tables and animations the pose asked for (present or not), sorted.</summary>
    public IReadOnlyList<uint> MotionInputs { get; init; } = [];
}
