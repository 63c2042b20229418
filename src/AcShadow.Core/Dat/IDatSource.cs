using AcShadow.Core.Dat.Objects;

namespace AcShadow.Core.Dat;

/// <summary>
/// Everything the domain needs from a dat: every export step (poses, shapes, BSP, cells, batch), the chart
/// and scene read through this seam only, so a package reader (Chorizite.DatReaderWriter) could replace
/// <see cref="DatDatabase"/> beneath them. What is not behind it: opening a file, checking its header and
/// sizing the object cache (<see cref="DatDatabase"/>, opened by the CLI's DatLocator, and batch builds its
/// own over the <see cref="DatArchive"/>), so such a reader would replace that opening code too; and doctor,
/// which checks the dat's own structure and works on <see cref="DatArchive"/> by design (docs/dat-layer.md).
/// Missing ids give null; a damaged object, whatever the damage, throws one
/// <see cref="DatFormatException"/> reading "corrupt dat: {kind} 0x{id} in {file}: …" with its
/// <see cref="DatFormatException.ObjectId"/> (an implementation catches its decoder's exceptions here).
/// </summary>
public interface IDatSource : IMotionSource
{
    DatSourceInfo Info { get; }
    Setup? ReadSetup(uint id);
    GfxObj? ReadGfxObj(uint id);
    LandBlockInfo? ReadLandBlockInfo(uint id);

    /// <summary>An indoor cell (cell dat); null when the source has none (the default for sources without cells).</summary>
    EnvCell? ReadEnvCell(uint id) => null;

    /// <summary>An Environment (portal dat); null when the source has none.</summary>
    CellEnvironment? ReadEnvironment(uint id) => null;

    IReadOnlyList<uint> ListIds(DatObjectKind kind);

    /// <summary>
    /// The bytes the dat's directory says an object takes (nothing is read or decoded); null when it is not
    /// in the dat or the source cannot say. A damaged directory can claim any size.
    /// </summary>
    long? StoredSize(uint id) => null;
}

/// <summary>What identifies the dat a result came from (recorded in index.json).</summary>
public sealed record DatSourceInfo(string FileName, long Size, DatFileKind Kind, int Iteration, int BlockSize)
{
    /// <summary>Where <see cref="Iteration"/> came from.</summary>
    public DatIterationSource IterationSource { get; init; } = DatIterationSource.Directory;

    /// <summary>
    /// The SHA-256 of the whole file (lowercase hex), when the run hashed it (batch and verify do,
    /// <see cref="DatArchive.ContentSha256"/>): what says two dats are the same dat, whatever their names.
    /// </summary>
    public string? Sha256 { get; init; }
}
