using AcShadow.Core.Export;
using AcShadow.Core.Formats;

namespace AcShadow.Core.Scenes;

/// <summary>
/// A scene's own output: its scene file and the BSP dumps of the bare GfxObjs it places (the Setups'
/// files come from the batch's Setup exports), plus the placed ids that could not be described.
/// <see cref="BspFiles"/> holds the dumps' bytes unless the engine streams them (then <see cref="BspEntries"/> lists what was written).
/// </summary>
public sealed record SceneExport(OutputFile SceneFile, IReadOnlyList<OutputFile> BspFiles, IReadOnlyList<FileEntry> BspEntries, IReadOnlyList<SkippedItem> Skipped);
