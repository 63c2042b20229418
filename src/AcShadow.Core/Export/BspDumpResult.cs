using AcShadow.Core.Formats;
using AcShadow.Core.Shapes;
using AcShadow.Fixtures.Shapes;

namespace AcShadow.Core.Export;

/// <summary>
/// A GfxObj's BSP dump: its canonical path (null when the GfxObj is absent or has no PhysicsBSP), its
/// bytes (null when the engine streams dumps to a sink), the entries of the files the sink wrote for it
/// (the canonical dump, or what the chosen formats made of it; empty without a sink: nothing hashes the
/// files of a `dump`) and the geometry diagnostics.
/// </summary>
public sealed record BspDumpResult(OutputFile? File, string? Path, IReadOnlyList<FileEntry> Entries, IReadOnlyList<Diagnostic> Diagnostics);
