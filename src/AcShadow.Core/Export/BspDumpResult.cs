using AcShadow.Core.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// A GfxObj's BSP dump: its canonical path (null when the GfxObj is absent or has no PhysicsBSP), its
/// bytes (null as well when the engine streams dumps to a sink), the entries of the files written for it
/// (the canonical dump, or what the chosen formats made of it) and the geometry diagnostics.
/// </summary>
public sealed record BspDumpResult(OutputFile? File, string? Path, IReadOnlyList<FileEntry> Entries, IReadOnlyList<Diagnostic> Diagnostics);
