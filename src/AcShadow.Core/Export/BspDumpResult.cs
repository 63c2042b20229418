using AcShadow.Core.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// A GfxObj's BSP dump: its entry (null when the GfxObj is absent or has no PhysicsBSP), its bytes
/// (null as well when the engine streams dumps to a sink) and the geometry diagnostics.
/// </summary>
public sealed record BspDumpResult(OutputFile? File, FileEntry? Entry, IReadOnlyList<Diagnostic> Diagnostics);
