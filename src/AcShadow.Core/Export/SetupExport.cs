using AcShadow.Core.Dat.Objects;
using AcShadow.Core.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// A Setup's export: its shadow file, the BSP dumps its shapes reference (<see cref="BspEntries"/>
/// always; <see cref="BspFiles"/>, their bytes, unless the engine streams dumps), and every diagnostic.
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
}
